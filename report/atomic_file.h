// Writing output files whole or not at all (docs/ARCHITECTURE.md, "Output"): the content goes to a
// temporary file beside the target, which is renamed into place only when fully written. What is
// not a regular file is never renamed over (issue 16): devices and pipes are written as streams.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace foresight {

// "-" as an output file: standard output.
inline constexpr std::string_view kStandardOutput = "-";

// Writes `content` to `file`: a regular file (or a new one) atomically, with SIGINT and SIGTERM
// held while the temporary file exists; through a symbolic link to the file it points to (the
// link stays); to a device or a FIFO (/dev/null, a named pipe) as a stream, never replacing it
// (and with signals not held: opening a FIFO waits for its reader); "-" to standard output;
// /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N to that open descriptor, after what
// was printed. Throws InputError naming the file when it cannot be written, or when it is a
// directory.
void WriteFileAtomically(const std::filesystem::path& file, std::string_view content);

// Checks, before a long run and without creating anything, that WriteFileAtomically can write
// `file`: not a directory, its folder exists and may be written in. Throws InputError
// "FLAG: FILE: problem". Streams ("-", devices, FIFOs) pass.
void CheckOutputFile(const std::filesystem::path& file, const std::string& flag);

}  // namespace foresight
