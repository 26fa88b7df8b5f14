#include "report/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "common/error.h"
#include "report/temporary_name.h"

namespace foresight {
namespace {

void WriteToDevice(const std::filesystem::path& file, std::string_view content,
                   const std::string& shown) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw InputError(shown + ": cannot write");
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.flush();
  if (!out) throw InputError(shown + ": write failed");
}

// The file a symbolic link names, followed link by link: for a dangling link the file it would
// name (std::filesystem::weakly_canonical stops at a dangling link and returns the link itself,
// which the rename would then replace with a regular file).
std::filesystem::path FollowLinks(const std::filesystem::path& link, const std::string& shown) {
  constexpr int kMaxLinks = 40;  // Linux's own limit (ELOOP)
  std::filesystem::path at = link;
  for (int hop = 0; hop < kMaxLinks; ++hop) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(at, ec))) {
      const std::filesystem::path resolved = std::filesystem::weakly_canonical(at, ec);
      if (ec) throw InputError(shown + ": cannot follow the symbolic link");
      return resolved;
    }
    const std::filesystem::path next = std::filesystem::read_symlink(at, ec);
    if (ec) throw InputError(shown + ": cannot follow the symbolic link");
    at = next.is_absolute() ? next : at.parent_path() / next;
  }
  throw InputError(shown + ": cannot follow the symbolic link (more than 40 links: a loop?)");
}

// /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N name a descriptor this process has
// open (a pipe, a terminal, or the file standard output was redirected to). Following the link
// fails for a pipe and, for a redirected standard output, would replace that file (losing what
// was printed); the content is written to the descriptor instead, after what was printed. Any
// other path to what standard output or error is (a link to /dev/stdout, the redirected file by
// its own name) is found by identity: the same device and inode.
std::optional<int> OwnDescriptor(const std::filesystem::path& file) {
  struct stat named {};
  if (::stat(file.c_str(), &named) == 0) {
    for (const int fd : {1, 2}) {
      struct stat open {};
      if (::fstat(fd, &open) == 0 && open.st_dev == named.st_dev && open.st_ino == named.st_ino) {
        return fd;
      }
    }
  }
  const std::string name = file.lexically_normal().string();
  if (name == "/dev/stdout") return 1;
  if (name == "/dev/stderr") return 2;
  for (const std::string& prefix :
       {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
        "/proc/" + std::to_string(::getpid()) + "/fd/"}) {
    if (!name.starts_with(prefix)) continue;
    const char* first = name.data() + prefix.size();
    const char* last = name.data() + name.size();
    int fd = -1;
    const auto [end, error] = std::from_chars(first, last, fd);
    if (error == std::errc() && end == last && first != last) return fd;
  }
  return std::nullopt;
}

void WriteToDescriptor(int fd, std::string_view content, const std::string& shown) {
  if (fd == 1) std::cout.flush();  // what was printed comes first
  if (fd == 2) std::cerr.flush();
  while (!content.empty()) {
    const ssize_t written = ::write(fd, content.data(), content.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) throw InputError(shown + ": write failed: " + std::strerror(errno));
    content.remove_prefix(static_cast<std::size_t>(written));
  }
}

// The folder of a regular output must exist and take a new file: a probe file is made and
// removed (a read-only file system or a full inode table shows here, also for root).
void CheckFolderTakesFiles(const std::filesystem::path& dir, const std::string& shown) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(shown + ": cannot write: directory " + dir.string() + " does not exist");
  }
  const std::filesystem::path probe = dir / (".foresight-probe-file." + UniqueSuffix());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0 && errno != EEXIST) {
    throw InputError(shown + ": cannot write in the folder " + dir.string() + ": " +
                     std::strerror(errno));
  }
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
  }
}

}  // namespace

FileTarget LocateOutputFile(const std::filesystem::path& file, const std::string& shown) {
  FileTarget target;
  if (file == kStandardOutput) {
    target.kind = FileTarget::Kind::kDescriptor;
    target.fd = 1;
    return target;
  }
  if (const std::optional<int> fd = OwnDescriptor(file)) {
    target.kind = FileTarget::Kind::kDescriptor;
    target.fd = *fd;
    return target;
  }
  std::error_code ec;
  // A symbolic link stays a link: the file it points to is replaced, atomically.
  target.target = file;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(file, ec))) {
    target.target = FollowLinks(file, shown);
  }
  const std::filesystem::file_status status = std::filesystem::status(target.target, ec);
  if (std::filesystem::is_directory(status)) throw InputError(shown + ": is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    target.kind = FileTarget::Kind::kStream;  // opened only when written: a FIFO waits
    return target;
  }
  CheckFolderTakesFiles(
      target.target.has_parent_path() ? target.target.parent_path() : ".", shown);
  return target;
}

void WriteNewFile(const std::filesystem::path& file, std::string_view content,
                  const std::string& shown) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError(shown + ": cannot write: " + std::strerror(errno));
  std::string failure;
  while (!content.empty()) {
    const ssize_t written = ::write(fd, content.data(), content.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      failure = written < 0 ? std::strerror(errno) : "nothing written";
      break;
    }
    content.remove_prefix(static_cast<std::size_t>(written));
  }
  // A failed close can mean lost data (NFS reports a full disk there).
  if (::close(fd) != 0 && failure.empty()) failure = std::strerror(errno);
  if (!failure.empty()) {
    ::unlink(file.c_str());
    throw InputError(shown + ": write failed: " + failure);
  }
}

void WriteStreamTarget(const FileTarget& target, std::string_view content,
                       const std::string& shown) {
  if (target.kind == FileTarget::Kind::kDescriptor) {
    return WriteToDescriptor(target.fd, content, shown);
  }
  WriteToDevice(target.target, content, shown);
}

}  // namespace foresight
