// All the outputs of one command, located and checked before the work and written together
// (docs/PROMISES.md, "Output").
//
// A command declares every output it will write (a file with AddFile, a report folder with
// AddFolder) before it starts the work; each is checked then, as it will be written: a file's
// folder must exist and take a new file (a probe file is made and removed), a report folder must
// be foresight's (report/report_folder.h) and its missing parents creatable (made and removed).
// Two outputs may not be one path, and a file inside a report folder becomes one of its files.
// An output may not name one of the command's inputs declared with AddInput (the input file
// itself, or a report folder that holds it, would be replaced), in whichever order they are
// declared, nor any data file the run has read while an InputLog is open (common/input_log.h:
// a situation's kick model, an experiment's --params), checked when the output is declared and
// again at Commit for the files read since.
//
// Commit() then writes the set: every regular file and folder is first staged as a temporary
// beside its target (a disk that fills up fails here, and the message names the user's path),
// and only when all are staged are they renamed into place, with SIGINT and SIGTERM held and the
// targets' folders locked (flock), so two runs into the same outputs commit one after the other,
// never interleaved. Streams (standard output, /dev/stdout, devices, FIFOs) cannot be staged; they
// are written after the files, with signals not held (opening a FIFO waits for its reader).
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "report/report_folder.h"

namespace foresight {

class OutputSet {
 public:
  OutputSet();
  ~OutputSet();
  OutputSet(OutputSet&&) noexcept;
  OutputSet& operator=(OutputSet&&) noexcept;

  // Declares and checks an output (an empty path: the flag was not given, nothing is declared).
  // Throws InputError naming `flag` and the path.
  void AddFile(const std::string& flag, const std::filesystem::path& file);
  void AddFolder(const std::string& flag, const std::filesystem::path& dir);
  bool Has(const std::string& flag) const;
  // Declares an input that no output may be or hold; `what` names it in the message ("the
  // shard folder", "--kicks"). An empty path declares nothing.
  void AddInput(const std::string& what, const std::filesystem::path& path);

  // The content of a declared output (a programmer's bug for an undeclared flag).
  void Put(const std::string& flag, std::string content);
  void Put(const std::string& flag, std::vector<ReportFile> files);

  // Writes every declared output (each must have its content). Throws InputError; when it
  // throws before a rename, no output has changed.
  void Commit();

 private:
  struct Output;
  struct Input;
  Output& Find(const std::string& flag);
  void RequireNotInput(const Output& output, const Input& input) const;
  void RequireNoneRead(const Output& output) const;  // common/input_log.h
  std::vector<std::unique_ptr<Output>> outputs_;
  std::vector<Input> inputs_;
};

// Writes `content` to `file`, an OutputSet of this one file: a regular file (or a new one)
// atomically; through a symbolic link to the file it points to (the link stays); to a device or
// a FIFO as a stream, never replacing it; "-" to standard output; /dev/stdout, /dev/stderr,
// /dev/fd/N and /proc/self/fd/N to that open descriptor, after what was printed. Throws
// InputError naming the file when it cannot be written, or when it is a directory.
void WriteFileAtomically(const std::filesystem::path& file, std::string_view content);

// Writes `files` (and the marker) as the report folder `dir`: an OutputSet of this one folder.
void WriteReportFolder(const std::filesystem::path& dir, std::span<const ReportFile> files,
                       std::string_view flag);

}  // namespace foresight
