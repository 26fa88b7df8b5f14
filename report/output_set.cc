#include "report/output_set.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>

#include "common/error.h"
#include "common/input_log.h"
#include "report/atomic_file.h"
#include "report/signal_guard.h"
#include "report/temporary_name.h"

namespace foresight {
namespace fs = std::filesystem;

struct OutputSet::Output {
  std::string flag;
  fs::path path;  // as the user gave it
  fs::path key;   // absolute and normal, to compare outputs
  bool folder = false;
  FileTarget file;
  Output* member_of = nullptr;  // a file directly inside a declared report folder
  std::optional<std::string> content;
  std::optional<std::vector<ReportFile>> files;

  std::string Shown() const { return flag.empty() ? path.string() : flag + ": " + path.string(); }
};

struct OutputSet::Input {
  std::string what;
  fs::path path;  // as the user gave it
  fs::path key;
};

namespace {

fs::path KeyOf(const fs::path& path) {
  std::error_code ec;
  fs::path key = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) key = fs::absolute(path, ec).lexically_normal();
  if (!key.has_filename() && key.has_parent_path()) key = key.parent_path();
  return key;
}

bool Inside(const fs::path& inner, const fs::path& outer) {
  const fs::path relative = inner.lexically_relative(outer);
  return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

// flock(2) on every folder the set renames into, taken in one order (device, inode) so that two
// runs never wait for each other crosswise; released when the descriptors close.
class FolderLocks {
 public:
  explicit FolderLocks(const std::vector<fs::path>& dirs) {
    std::vector<std::pair<std::pair<dev_t, ino_t>, int>> opened;
    for (const fs::path& dir : dirs) {
      const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      struct stat info {};
      if (fd < 0) continue;  // renaming into it fails later, with the reason
      ::fstat(fd, &info);
      const std::pair<dev_t, ino_t> id{info.st_dev, info.st_ino};
      const bool seen = std::any_of(opened.begin(), opened.end(),
                                    [&](const auto& other) { return other.first == id; });
      if (seen) {
        ::close(fd);
      } else {
        opened.push_back({id, fd});
      }
    }
    std::sort(opened.begin(), opened.end());
    for (const auto& [id, fd] : opened) {
      // A file system without flock (some network ones) commits without the lock.
      while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
      }
      fds_.push_back(fd);
    }
  }
  ~FolderLocks() {
    for (const int fd : fds_) ::close(fd);
  }
  FolderLocks(const FolderLocks&) = delete;
  FolderLocks& operator=(const FolderLocks&) = delete;

 private:
  std::vector<int> fds_;
};

fs::path FolderOf(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

}  // namespace

OutputSet::OutputSet() = default;
OutputSet::~OutputSet() = default;
OutputSet::OutputSet(OutputSet&&) noexcept = default;
OutputSet& OutputSet::operator=(OutputSet&&) noexcept = default;

void OutputSet::AddFolder(const std::string& flag, const fs::path& dir) {
  if (dir.empty()) return;
  auto output = std::make_unique<Output>();
  output->flag = flag;
  output->path = dir;
  output->folder = true;
  output->key = KeyOf(NormalReportFolder(dir, flag));
  for (const auto& other : outputs_) {
    if (other->key == output->key || Inside(other->key, output->key) ||
        Inside(output->key, other->key)) {
      throw InputError(output->Shown() + ": overlaps " + other->Shown() +
                       "; give the outputs separate places");
    }
  }
  for (const Input& input : inputs_) RequireNotInput(*output, input);
  RequireNoneRead(*output);
  CheckReportFolder(dir, flag);
  outputs_.push_back(std::move(output));
}

void OutputSet::AddFile(const std::string& flag, const fs::path& file) {
  if (file.empty()) return;
  auto output = std::make_unique<Output>();
  output->flag = flag;
  output->path = file;
  output->key = file == kStandardOutput ? fs::path(kStandardOutput) : KeyOf(file);
  for (const auto& other : outputs_) {
    if (other->folder && output->key.parent_path() == other->key) {
      output->member_of = other.get();  // becomes one of the report's files
      continue;
    }
    if (other->key == output->key || (other->folder && Inside(output->key, other->key))) {
      throw InputError(output->Shown() + ": is also " + other->Shown() +
                       (other->folder ? " (a file in one of its sub-folders)" : "") +
                       "; give every output its own place");
    }
  }
  for (const Input& input : inputs_) RequireNotInput(*output, input);
  RequireNoneRead(*output);
  if (!output->member_of) output->file = LocateOutputFile(file, output->Shown());
  outputs_.push_back(std::move(output));
}

void OutputSet::AddInput(const std::string& what, const fs::path& path) {
  if (path.empty()) return;
  Input input{what, path, KeyOf(path)};
  for (const auto& output : outputs_) RequireNotInput(*output, input);
  inputs_.push_back(std::move(input));
}

void OutputSet::RequireNotInput(const Output& output, const Input& input) const {
  const bool is = output.key == input.key;
  if (!is && !(output.folder && Inside(input.key, output.key))) return;
  throw InputError(output.Shown() + (is ? " is " : " holds ") + input.what + " " +
                   input.path.string() +
                   ", which the output would replace; write the output elsewhere");
}

void OutputSet::RequireNoneRead(const Output& output) const {
  for (const fs::path& file : InputLog::Files()) {
    const fs::path key = KeyOf(file);
    if (output.key == key) {
      throw InputError(output.Shown() +
                       " is a file this run read, which the output would replace; write the "
                       "output elsewhere");
    }
    if (output.folder && Inside(key, output.key)) {
      throw InputError(output.Shown() + " holds " + file.string() +
                       ", a file this run read, which the output would replace; write the "
                       "output elsewhere");
    }
  }
}

bool OutputSet::Has(const std::string& flag) const {
  return std::any_of(outputs_.begin(), outputs_.end(),
                     [&](const auto& o) { return o->flag == flag; });
}

OutputSet::Output& OutputSet::Find(const std::string& flag) {
  for (const auto& output : outputs_) {
    if (output->flag == flag) return *output;
  }
  throw std::logic_error("OutputSet: no output " + flag + " was declared");
}

void OutputSet::Put(const std::string& flag, std::string content) {
  Output& output = Find(flag);
  if (output.folder) throw std::logic_error("OutputSet: " + flag + " is a folder");
  output.content = std::move(content);
}

void OutputSet::Put(const std::string& flag, std::vector<ReportFile> files) {
  Output& output = Find(flag);
  if (!output.folder) throw std::logic_error("OutputSet: " + flag + " is a file");
  output.files = std::move(files);
}

void OutputSet::Commit() {
  std::vector<Output*> files, folders, streams;
  // Files read after the outputs were declared (the work reads some) are checked now.
  for (const auto& output : outputs_) RequireNoneRead(*output);
  for (const auto& output : outputs_) {
    if (!(output->folder ? output->files.has_value() : output->content.has_value())) {
      throw std::logic_error("OutputSet: no content for " + output->Shown());
    }
    if (output->folder) {
      folders.push_back(output.get());
    } else if (output->member_of) {
      output->member_of->files->push_back({output->key.filename().string(), *output->content});
    } else if (output->file.kind == FileTarget::Kind::kRegular) {
      files.push_back(output.get());
    } else {
      streams.push_back(output.get());
    }
  }
  std::vector<fs::path> locked;
  for (const Output* folder : folders) {
    const fs::path parent = FolderOf(NormalReportFolder(folder->path, folder->flag));
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) {
      throw InputError(folder->Shown() + ": cannot create its parent folder: " + ec.message());
    }
    locked.push_back(parent);
  }
  for (const Output* file : files) locked.push_back(FolderOf(file->file.target));
  {
    const FolderLocks locks(locked);
    const SignalGuard hold_signals;  // no temporary outlives an interrupted run
    std::vector<StagedFolder> staged_folders;
    std::vector<fs::path> staged_files;
    std::size_t installed_files = 0;
    try {
      for (const Output* folder : folders) {
        staged_folders.push_back(
            StageReportFolder(folder->path, *folder->files, folder->flag));
      }
      for (const Output* file : files) {
        fs::path temp = file->file.target;
        temp += ".tmp." + UniqueSuffix();
        WriteNewFile(temp, *file->content, file->Shown());
        staged_files.push_back(temp);
      }
      for (StagedFolder& staged : staged_folders) PrepareInstall(staged);
      // Everything is staged: only renames remain.
      for (StagedFolder& staged : staged_folders) InstallReportFolder(staged);
      for (; installed_files < files.size(); ++installed_files) {
        if (::rename(staged_files[installed_files].c_str(),
                     files[installed_files]->file.target.c_str()) != 0) {
          throw InputError(files[installed_files]->Shown() +
                           ": cannot move the finished file into place: " +
                           std::strerror(errno));
        }
      }
    } catch (...) {
      for (const StagedFolder& staged : staged_folders) DiscardStagedFolder(staged);
      for (std::size_t i = installed_files; i < staged_files.size(); ++i) {
        ::unlink(staged_files[i].c_str());
      }
      throw;
    }
  }
  for (const Output* stream : streams) {
    WriteStreamTarget(stream->file, *stream->content, stream->Shown());
  }
}

void WriteFileAtomically(const fs::path& file, std::string_view content) {
  OutputSet outputs;
  outputs.AddFile("", file);
  outputs.Put("", std::string(content));
  outputs.Commit();
}

void WriteReportFolder(const fs::path& dir, std::span<const ReportFile> files,
                       std::string_view flag) {
  OutputSet outputs;
  outputs.AddFolder(std::string(flag), dir);
  outputs.Put(std::string(flag), std::vector<ReportFile>(files.begin(), files.end()));
  outputs.Commit();
}

}  // namespace foresight
