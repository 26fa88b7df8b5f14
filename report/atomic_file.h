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
// (An OutputSet of this one file, report/output_set.h.)
void WriteFileAtomically(const std::filesystem::path& file, std::string_view content);

// The pieces OutputSet is made of.
struct FileTarget {
  enum class Kind { kRegular, kStream, kDescriptor };
  Kind kind = Kind::kRegular;
  std::filesystem::path target;  // a regular file: the file replaced (a link's target)
  int fd = -1;                   // kDescriptor: 1 for "-" and /dev/stdout, ...
};
// Where `file` is written and how; `shown` starts the messages ("--svg: out/a.svg"). Throws
// InputError for a directory and for a regular file whose folder does not exist or takes no
// new file (found by making and removing a probe file). Opens nothing that could block.
FileTarget LocateOutputFile(const std::filesystem::path& file, const std::string& shown);
// Creates `file` (it must not exist) with `content`, checking every write and the close; on
// failure removes it and throws InputError "SHOWN: write failed: REASON".
void WriteNewFile(const std::filesystem::path& file, std::string_view content,
                  const std::string& shown);
// Writes a stream target (a device, a FIFO, an open descriptor).
void WriteStreamTarget(const FileTarget& target, std::string_view content,
                       const std::string& shown);

}  // namespace foresight
