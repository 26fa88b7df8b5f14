#include "report/report_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "common/error.h"
#include "report/atomic_file.h"
#include "report/signal_guard.h"

namespace foresight {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void Refuse(std::string_view flag, const fs::path& dir, const std::string& why) {
  throw InputError(std::string(flag) + ": " + dir.string() + ": " + why);
}

// "out/fidelity/" and "out/fidelity" name the same folder; "." and ".." name none we may swap.
fs::path Normal(const fs::path& dir, std::string_view flag) {
  fs::path normal = dir.lexically_normal();
  if (!normal.has_filename() && normal.has_parent_path()) normal = normal.parent_path();
  const std::string name = normal.filename().string();
  if (name.empty() || name == "." || name == "..") {
    Refuse(flag, dir, "name a report folder of its own (not the current or a parent folder)");
  }
  return normal;
}

fs::path ParentOf(const fs::path& dir) {
  return dir.has_parent_path() ? dir.parent_path() : fs::path(".");
}

// The nearest existing folder at or above `dir` must be writable (the rest is created).
void CheckWritableAncestor(const fs::path& dir, std::string_view flag) {
  std::error_code ec;
  fs::path existing = fs::absolute(dir, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path()) {
    existing = existing.parent_path();
  }
  const std::string cannot =
      std::string(flag) + ": cannot create the folder '" + dir.string() + "': ";
  if (!fs::is_directory(existing, ec)) {
    throw InputError(cannot + existing.string() + " is a file, not a folder");
  }
  if (::access(existing.c_str(), W_OK) != 0)
    throw InputError(cannot + existing.string() + " is not writable");
}

void CheckReplaceable(const fs::path& dir, std::string_view flag) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) Refuse(flag, dir, "exists and is not a folder");
  if (fs::is_empty(dir, ec) || fs::exists(dir / kReportMarker, ec)) return;
  Refuse(flag, dir,
         "holds files that no foresight report wrote; the whole folder is replaced, so choose a "
         "new or empty folder");
}

void SwapInto(const fs::path& temp, const fs::path& dir, std::string_view flag) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec))) {
    fs::rename(temp, dir, ec);
    if (!ec) return;  // else another run made it meanwhile: exchange with that one
  }
  if (::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) return;
  if (errno != EINVAL && errno != ENOSYS) {
    Refuse(flag, dir, std::string("cannot replace the folder: ") + std::strerror(errno));
  }
  // No atomic exchange on this file system: the folder is briefly absent, never mixed.
  const fs::path old = fs::path(temp).concat(".old");
  fs::rename(dir, old, ec);
  if (!ec) fs::rename(temp, dir, ec);
  if (ec) Refuse(flag, dir, "cannot replace the folder: " + ec.message());
  fs::rename(old, temp, ec);
}

}  // namespace

void CheckReportFolder(const fs::path& dir, std::string_view flag) {
  const fs::path normal = Normal(dir, flag);
  CheckWritableAncestor(normal, flag);
  CheckReplaceable(normal, flag);
}

namespace {
// Distinguishes the temporary folders of writers within one process (pid tells processes apart).
std::atomic<unsigned> write_count{0};
}  // namespace

void WriteReportFolder(const fs::path& dir, std::span<const ReportFile> files,
                       std::string_view flag) {
  const fs::path normal = Normal(dir, flag);
  CheckReportFolder(normal, flag);
  const SignalGuard hold_signals;  // the temporary folder never outlives an interrupted run
  std::error_code ec;
  fs::create_directories(ParentOf(normal), ec);
  if (ec) Refuse(flag, dir, "cannot create its parent folder: " + ec.message());
  // Built piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string temp_name = ".";
  temp_name += normal.filename().string();
  temp_name += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(++write_count);
  const fs::path temp = ParentOf(normal) / temp_name;
  fs::remove_all(temp, ec);
  if (!fs::create_directory(temp, ec)) Refuse(flag, dir, "cannot create " + temp.string());
  try {
    for (const ReportFile& file : files) WriteFileAtomically(temp / file.name, file.content);
    WriteFileAtomically(temp / kReportMarker,
                        "written by foresight; the folder is replaced whole\n");
    SwapInto(temp, normal, flag);
  } catch (...) {
    fs::remove_all(temp, ec);
    throw;
  }
  fs::remove_all(temp, ec);  // the old report, if there was one
}

}  // namespace foresight
