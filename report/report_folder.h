// A report folder written whole: a reader sees the old report or the new one, never a mix, and
// a user's own files in the folder are kept.
//
// How: the files go to a hidden sibling folder ".NAME.tmp.PID.N" that is swapped with the report
// folder in one step (renameat2 RENAME_EXCHANGE; where the file system lacks it, two renames).
// Every report folder holds the marker kReportMarker, which lists the files foresight wrote
// there. Before the swap, every other entry of the old folder (a user's notes, a sub-folder) is
// moved into the new one; the old report, now holding only what foresight wrote, is removed.
// A folder is foresight's only when it does not exist, is empty, or holds a marker that
// foresight wrote (its first line is kMarkerHeader); anything else (".", a folder of the user's,
// one with an empty or foreign ".foresight-report") is refused before the work, with the reason.
// A user's file with the name of a file the new report writes is refused too, never replaced.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace foresight {

inline constexpr std::string_view kReportMarker = ".foresight-report";
inline constexpr std::string_view kMarkerHeader =
    "foresight report folder: foresight wrote the files listed below and replaces them on its "
    "next run; every other file here is kept";

struct ReportFile {
  std::string name;  // inside the folder, no sub-folders
  std::string content;
};

// The steps OutputSet takes, folder by folder (report/output_set.h; its WriteReportFolder writes
// one folder).

// Throws InputError naming `flag` if `dir` could not be written as a report folder: not
// foresight's, a parent that cannot be created (made and removed again to find out). OutputSet
// calls it when the folder is declared, before the work; staging checks again.
void CheckReportFolder(const std::filesystem::path& dir, std::string_view flag);

struct StagedFolder {
  std::string flag;
  std::filesystem::path dir;   // normalised
  std::filesystem::path temp;  // the new report, complete
  std::vector<std::string> names;  // the files the new report writes
  std::vector<std::string> kept;   // the user's entries of the old folder
  bool swapped = false;
};
// "out/r/" and "out/r" name the same folder; "." and ".." are refused.
std::filesystem::path NormalReportFolder(const std::filesystem::path& dir, std::string_view flag);
// Writes the new report into a temporary sibling folder (creating the parents).
StagedFolder StageReportFolder(const std::filesystem::path& dir, std::span<const ReportFile> files,
                               std::string_view flag);
// Checks ownership again and lists the user's entries to keep (call with the parent locked).
void PrepareInstall(StagedFolder& staged);
// Moves the user's entries into the new report, swaps it into place and removes the old one.
void InstallReportFolder(StagedFolder& staged);
// Removes what is left of a staged folder that was not installed (never a user's entry).
void DiscardStagedFolder(const StagedFolder& staged);

}  // namespace foresight
