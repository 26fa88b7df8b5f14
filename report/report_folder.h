// A report folder written whole (issue 16): a reader sees the old report or the new one, never a
// mix, whatever fails, and two runs into the same folder cannot interleave their files.
//
// How: the files go to a hidden sibling folder ".NAME.tmp.PID" that is swapped with the report
// folder in one step (renameat2 RENAME_EXCHANGE; where the file system lacks it, two renames),
// and the old report is then removed. Because the old folder is removed, only a folder that
// foresight made may be replaced: one that does not exist, is empty, or holds the marker file
// kReportMarker that every report folder gets. Anything else (".", a folder of the user's) is
// refused before the work, with the reason.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace foresight {

inline constexpr std::string_view kReportMarker = ".foresight-report";

struct ReportFile {
  std::string name;  // inside the folder, no sub-folders
  std::string content;
};

// Throws InputError naming `flag` if `dir` could not be written as a report folder. Call it
// before the work; WriteReportFolder checks again.
void CheckReportFolder(const std::filesystem::path& dir, std::string_view flag);

// Writes `files` (and the marker) as the folder `dir`, replacing a previous report there.
void WriteReportFolder(const std::filesystem::path& dir, std::span<const ReportFile> files,
                       std::string_view flag);

}  // namespace foresight
