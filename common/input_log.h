// The data files a run has read, so that none of its outputs replaces one (report/output_set.h):
// not only the inputs a command names (--situation, --kicks) but every file they lead to (a
// situation's kick model, an experiment's --params and the files it names). ReadDataFile
// (common/data_file.h) records each file it reads while a log is open; a command's run opens one
// (app/cli_main.h, tools/tool_main.h). Without an open log nothing is recorded: a library linked
// into robot code, the Python module and the unit tests pay nothing and change nothing.
//
// Thread-safe: workers read files while the log is open.
#pragma once

#include <filesystem>
#include <vector>

namespace foresight {

class InputLog {
 public:
  // Opens the log for this scope (logs do not nest: the inner one is a programmer's error).
  InputLog();
  ~InputLog();
  InputLog(const InputLog&) = delete;
  InputLog& operator=(const InputLog&) = delete;

  // Records `file` if a log is open.
  static void Record(const std::filesystem::path& file);
  // A file an output may replace although it was read: a kick model recalibrated into itself
  // (`calibrate --kicks K --out K`). Ignored without an open log.
  static void Allow(const std::filesystem::path& file);
  // The files read and not allowed so far, in the order first read; empty without a log.
  static std::vector<std::filesystem::path> Files();
};

}  // namespace foresight
