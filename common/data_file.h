// Reading a data file whole: the one way every reader opens what a user names (JSON, URDF,
// meshes, CSV logs, case and shard files). A name that is not a regular file (a folder,
// /dev/zero, a FIFO, whose open would block with no writer) or a file larger than the reader
// allows is a one-line InputError before anything is opened or allocated.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace foresight {

// The size a data file may have unless its reader says otherwise (the largest shipped file is
// under 100 kB; a URDF, a case base's file or a log of thousands of kicks stays far below).
inline constexpr std::uintmax_t kMaxDataFileBytes = 16u << 20;  // 16 MiB

// Throws InputError "FILE: problem" unless `file` is a regular file of at most `max_bytes`.
void RequireDataFile(const std::filesystem::path& file,
                     std::uintmax_t max_bytes = kMaxDataFileBytes);

// The whole file after RequireDataFile; reads at most max_bytes even if the file grows meanwhile.
std::string ReadDataFile(const std::filesystem::path& file,
                         std::uintmax_t max_bytes = kMaxDataFileBytes);

}  // namespace foresight
