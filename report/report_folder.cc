#include "report/report_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include "common/error.h"
#include "report/atomic_file.h"
#include "report/temporary_name.h"

namespace foresight {
namespace fs = std::filesystem;
namespace {

// What a marker written before it listed its files said; such a folder is foresight's, and of
// its files those the new report writes are replaced (the rest is kept: nothing says whose).
constexpr std::string_view kLegacyMarkerHeader =
    "written by foresight; the folder is replaced whole";
// A marker is a short list of names; anything larger is not one foresight wrote.
constexpr std::uintmax_t kMaxMarkerBytes = 1 << 20;

[[noreturn]] void Refuse(std::string_view flag, const fs::path& dir, const std::string& why) {
  throw InputError(std::string(flag) + ": " + dir.string() + ": " + why);
}

fs::path ParentOf(const fs::path& dir) {
  return dir.has_parent_path() ? dir.parent_path() : fs::path(".");
}

// The files a folder's marker says foresight wrote; nullopt when the folder has no marker that
// foresight wrote (none, empty, foreign, not a regular file).
struct Marker {
  bool legacy = false;
  std::set<std::string> listed;
};
std::optional<Marker> ReadMarker(const fs::path& dir) {
  std::error_code ec;
  const fs::path file = dir / kReportMarker;
  if (!fs::is_regular_file(fs::symlink_status(file, ec))) return std::nullopt;
  if (fs::file_size(file, ec) > kMaxMarkerBytes || ec) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!std::getline(in, line)) return std::nullopt;
  Marker marker;
  if (line == kLegacyMarkerHeader) {
    marker.legacy = true;
    return marker;
  }
  if (line != kMarkerHeader) return std::nullopt;
  while (std::getline(in, line)) {
    if (!line.empty()) marker.listed.insert(line);
  }
  return marker;
}

// The nearest existing folder at or above `dir` (the report folder `named`'s parent) must be a
// folder in which the missing ones can
// be made: they are made and removed again (a read-only file system, a name too long, a file in
// the way all show here, also for root, whom access(2) would let pass).
void CheckCreatable(const fs::path& dir, std::string_view flag, const fs::path& named) {
  std::error_code ec;
  std::vector<fs::path> missing;
  fs::path existing = fs::absolute(dir, ec);
  while (!existing.empty() && !fs::exists(fs::symlink_status(existing, ec)) &&
         existing != existing.parent_path()) {
    missing.push_back(existing);
    existing = existing.parent_path();
  }
  const std::string cannot =
      std::string(flag) + ": cannot create the folder '" + named.string() + "': ";
  if (!fs::is_directory(existing, ec)) {
    throw InputError(cannot + existing.string() + " is a file, not a folder");
  }
  std::vector<fs::path> made;
  std::string failure;
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (::mkdir(it->c_str(), 0777) == 0) {
      made.push_back(*it);
    } else if (errno != EEXIST) {  // another run made it meanwhile: fine, and not ours to remove
      failure = it->string() + ": " + std::strerror(errno);
      break;
    }
  }
  if (missing.empty()) {  // the folder exists: it must take a new entry
    const fs::path probe = existing / (".foresight-probe-folder." + UniqueSuffix());
    if (::mkdir(probe.c_str(), 0777) != 0) {
      failure = existing.string() + ": " + std::strerror(errno);
    } else {
      made.push_back(probe);
    }
  }
  for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
  if (!failure.empty()) throw InputError(cannot + failure);
}

// Ownership, before the work and again before the swap.
std::optional<Marker> RequireOwn(const fs::path& dir, std::string_view flag) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return std::nullopt;
  if (fs::is_symlink(status)) {
    // The report replaces the folder whole (a rename), which would put a folder where the link
    // is; the folder it names is the one to give.
    Refuse(flag, dir, "is a symbolic link (to " + fs::read_symlink(dir, ec).string() +
                          "): a report folder is replaced whole, give the folder itself");
  }
  if (!fs::is_directory(status)) Refuse(flag, dir, "exists and is not a folder");
  if (fs::is_empty(dir, ec)) return std::nullopt;
  if (std::optional<Marker> marker = ReadMarker(dir)) return marker;
  Refuse(flag, dir,
         "holds files that no foresight report wrote (no " + std::string(kReportMarker) +
             " marker that foresight wrote); choose a new or empty folder");
}

std::string MarkerText(std::span<const std::string> names) {
  std::string text(kMarkerHeader);
  text += "\n";
  for (const std::string& name : names) text += name + "\n";
  return text;
}

// Moves the entries `names` from `from` into `to`; on failure moves back those moved.
void MoveEntries(const fs::path& from, const fs::path& to, std::span<const std::string> names,
                 const StagedFolder& staged) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::error_code ec;
    fs::rename(from / names[i], to / names[i], ec);
    if (!ec) continue;
    for (std::size_t j = 0; j < i; ++j) fs::rename(to / names[j], from / names[j], ec);
    Refuse(staged.flag, staged.dir,
           "cannot keep the user's entry '" + names[i] + "': " + ec.message());
  }
}

}  // namespace

fs::path NormalReportFolder(const fs::path& dir, std::string_view flag) {
  fs::path normal = dir.lexically_normal();
  if (!normal.has_filename() && normal.has_parent_path()) normal = normal.parent_path();
  const std::string name = normal.filename().string();
  if (name.empty() || name == "." || name == "..") {
    Refuse(flag, dir, "name a report folder of its own (not the current or a parent folder)");
  }
  return normal;
}

void CheckReportFolder(const fs::path& dir, std::string_view flag) {
  const fs::path normal = NormalReportFolder(dir, flag);
  CheckCreatable(ParentOf(normal), flag, dir);
  RequireOwn(normal, flag);
}

StagedFolder StageReportFolder(const fs::path& dir, std::span<const ReportFile> files,
                               std::string_view flag) {
  StagedFolder staged;
  staged.flag = flag;
  staged.dir = NormalReportFolder(dir, flag);
  std::error_code ec;
  fs::create_directories(ParentOf(staged.dir), ec);
  if (ec) Refuse(flag, dir, "cannot create its parent folder: " + ec.message());
  // Built piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string temp_name = ".";
  temp_name += staged.dir.filename().string();
  temp_name += ".tmp." + UniqueSuffix();
  staged.temp = ParentOf(staged.dir) / temp_name;
  fs::remove_all(staged.temp, ec);
  if (::mkdir(staged.temp.c_str(), 0777) != 0) {
    Refuse(flag, dir, std::string("cannot create a folder beside it: ") + std::strerror(errno));
  }
  try {
    for (const ReportFile& file : files) {
      if (file.name.find('/') != std::string::npos || file.name == kReportMarker) {
        Refuse(flag, dir, "'" + file.name + "' is not a file name in the folder");
      }
      if (std::find(staged.names.begin(), staged.names.end(), file.name) != staged.names.end()) {
        Refuse(flag, dir, "two outputs would be its file '" + file.name + "'");
      }
      WriteNewFile(staged.temp / file.name, file.content,
                   std::string(flag) + ": " + (staged.dir / file.name).string());
      staged.names.push_back(file.name);
    }
    WriteNewFile(staged.temp / kReportMarker, MarkerText(staged.names),
                 std::string(flag) + ": " + (staged.dir / kReportMarker).string());
  } catch (...) {
    DiscardStagedFolder(staged);
    throw;
  }
  return staged;
}

void PrepareInstall(StagedFolder& staged) {
  const std::optional<Marker> marker = RequireOwn(staged.dir, staged.flag);
  staged.kept.clear();
  if (!marker) return;
  const std::set<std::string> writes(staged.names.begin(), staged.names.end());
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(staged.dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == kReportMarker) continue;
    const bool foresights =
        marker->legacy ? writes.contains(name) : marker->listed.contains(name);
    if (foresights) continue;
    if (writes.contains(name)) {
      Refuse(staged.flag, staged.dir,
             "holds '" + name +
                 "', which foresight did not write and the report would replace; move it away");
    }
    staged.kept.push_back(name);
  }
  std::sort(staged.kept.begin(), staged.kept.end());
}

void InstallReportFolder(StagedFolder& staged) {
  const fs::path& dir = staged.dir;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec))) {
    fs::rename(staged.temp, dir, ec);
    if (!ec) {
      staged.swapped = true;
      return;
    }
    PrepareInstall(staged);  // another run made it meanwhile: exchange with that one
  }
  MoveEntries(dir, staged.temp, staged.kept, staged);
  if (::renameat2(AT_FDCWD, staged.temp.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
    const int error = errno;
    if (error != EINVAL && error != ENOSYS) {
      MoveEntries(staged.temp, dir, staged.kept, staged);
      Refuse(staged.flag, dir, std::string("cannot replace the folder: ") + std::strerror(error));
    }
    // No atomic exchange on this file system: the folder is briefly absent, never mixed.
    const fs::path old = fs::path(staged.temp).concat(".old");
    fs::rename(dir, old, ec);
    if (!ec) fs::rename(staged.temp, dir, ec);
    if (ec) {
      const std::string why = ec.message();
      fs::rename(old, dir, ec);
      MoveEntries(staged.temp, dir, staged.kept, staged);
      Refuse(staged.flag, dir, "cannot replace the folder: " + why);
    }
    fs::rename(old, staged.temp, ec);
  }
  staged.swapped = true;
  fs::remove_all(staged.temp, ec);  // the old report, which holds only what foresight wrote
}

void DiscardStagedFolder(const StagedFolder& staged) {
  if (staged.swapped || staged.temp.empty()) return;
  std::error_code ec;
  fs::remove_all(staged.temp, ec);
}

}  // namespace foresight
