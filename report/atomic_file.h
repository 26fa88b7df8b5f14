// Writing output files whole or not at all (docs/ARCHITECTURE.md, "Output"): the content goes to a
// temporary file beside the target, which is renamed into place only when fully written.
#pragma once

#include <filesystem>
#include <string_view>

namespace foresight {

// Throws InputError naming the file when it cannot be written.
void WriteFileAtomically(const std::filesystem::path& file, std::string_view content);

}  // namespace foresight
