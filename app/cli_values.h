// Strict parsing of command-line values: the whole text must be the number, in range, or the
// command fails with "--flag: must be ..., got 'TEXT'" (CLI11's conversions accept "-1" for an
// unsigned seed and wrap it around).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace foresight {

int ParseCount(const std::string& flag, const std::string& text, int lo, int hi);
std::uint64_t ParseSeed(const std::string& text);  // for --seed: 0 .. 2^64 - 1
double ParseNumber(const std::string& flag, const std::string& text, double lo, double hi);

// A library setting's default as the command line shows it, so the default lives in one place
// (the settings struct): integers in full, numbers in the shortest form ("0.95", not "0.950000").
std::string DefaultText(double value);

// Progress "LABEL done / total UNIT" on stderr, only when stderr is a terminal
// (docs/ARCHITECTURE.md, "Output").
std::function<void(int, int)> TerminalProgress(const std::string& label, const std::string& unit);

// Creates a report folder (and its parents); InputError naming the flag and folder if it fails.
void CreateReportDir(const std::string& dir, const std::string& flag);
// Creates the report folder `dir` (CreateReportDir) and writes every file of it atomically.
// Call it only once every content is computed, so a failed run leaves nothing half-written.
using ReportFiles = std::vector<std::pair<std::filesystem::path, std::string>>;
void WriteReportFiles(const std::string& dir, const std::string& flag, const ReportFiles& files);

// Checks, without creating anything, that CreateReportDir can succeed: the folder is a folder
// or can be made in its nearest existing ancestor, which must be writable. For long runs, so
// that a bad flag fails before the work instead of after it.
void CheckReportDir(const std::string& dir, const std::string& flag);

}  // namespace foresight
