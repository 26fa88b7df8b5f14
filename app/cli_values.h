// Strict parsing of command-line values: the whole text must be the number, in range, or the
// command fails with "--flag: must be ..., got 'TEXT'" (CLI11's conversions accept "-1" for an
// unsigned seed and wrap it around).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/output_set.h"

namespace foresight {

int ParseCount(const std::string& flag, const std::string& text, int lo, int hi);
std::uint64_t ParseSeed(const std::string& text);  // for --seed: 0 .. 2^64 - 1
double ParseNumber(const std::string& flag, const std::string& text, double lo, double hi);
// "on" or "off" (empty: not given, nullopt); anything else is an InputError naming the flag.
std::optional<bool> ParseSwitch(const std::string& flag, const std::string& text);

// A long loop's progress "LABEL: done / total UNIT (..%), rate, time left": to the long-call
// host of the calling thread if there is one (the Python module's callback, common/long_call.h),
// otherwise on stderr: rewritten in place on a terminal, a line at most every few seconds in a
// log (common/progress_log.h; docs/ARCHITECTURE.md, "Output"). Make it on the thread that runs
// the loop.
std::function<void(int, int)> CommandProgress(const std::string& label, const std::string& unit);

// A command's report folder: the files, given as paths in the folder, as an OutputSet's folder
// content (report/output_set.h).
using ReportFiles = std::vector<std::pair<std::filesystem::path, std::string>>;
std::vector<ReportFile> ReportFolderFiles(const ReportFiles& files);

// An OutputSet holding the report folder `dir` of the flag --out, declared and so checked now:
// call it before the work, put the files in and commit them after it.
OutputSet ReportFolderOutput(const std::string& dir);

}  // namespace foresight
