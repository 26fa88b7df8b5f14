// The pieces of writing one output file (report/output_set.h puts them together; its
// WriteFileAtomically writes one file): where a file is written and how, a new file written and
// checked, a stream written. What is not a regular file is never renamed over: devices and pipes
// are written as streams.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace foresight {

// "-" as an output file: standard output.
inline constexpr std::string_view kStandardOutput = "-";

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
