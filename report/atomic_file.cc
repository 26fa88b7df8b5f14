#include "report/atomic_file.h"

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
#include "report/signal_guard.h"

namespace foresight {
namespace {

// Devices, pipes and "-" take the content as a stream: there is nothing to rename into place,
// and renaming over them would replace /dev/null or a FIFO with a regular file.
void WriteStream(std::ostream& out, const std::string& name, std::string_view content) {
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.flush();
  if (!out) throw InputError(name + ": write failed");
}

void WriteToDevice(const std::filesystem::path& file, std::string_view content) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw InputError(file.string() + ": cannot write");
  WriteStream(out, file.string(), content);
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

void WriteToDescriptor(int fd, const std::filesystem::path& file, std::string_view content) {
  if (fd == 1) std::cout.flush();  // what was printed comes first
  if (fd == 2) std::cerr.flush();
  while (!content.empty()) {
    const ssize_t written = ::write(fd, content.data(), content.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      throw InputError(file.string() + ": write failed: " + std::strerror(errno));
    }
    content.remove_prefix(static_cast<std::size_t>(written));
  }
}

void WriteRegularFile(const std::filesystem::path& shown, const std::filesystem::path& file,
                      std::string_view content) {
  const SignalGuard hold_signals;  // a temporary file never outlives an interrupted run
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(shown.string() + ": cannot write: directory " + dir.string() +
                     " does not exist");
  }
  std::filesystem::path temp = file;
  temp += ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(shown.string() + ": cannot write file");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();  // checked: a failed close can mean lost data
    if (!out) {
      std::filesystem::remove(temp, ec);
      throw InputError(shown.string() + ": write failed");
    }
  }
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    throw InputError(shown.string() + ": cannot move the finished file into place");
  }
}

}  // namespace

void WriteFileAtomically(const std::filesystem::path& file, std::string_view content) {
  // Streams leave no temporary file, so signals are held only around the regular file's write:
  // opening a FIFO blocks until a reader comes, and Ctrl-C must still end the run then.
  if (file == kStandardOutput) return WriteStream(std::cout, "standard output", content);
  if (const std::optional<int> fd = OwnDescriptor(file)) {
    return WriteToDescriptor(*fd, file, content);
  }
  std::error_code ec;
  // A symbolic link stays a link: the file it points to is replaced, atomically.
  std::filesystem::path target = file;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(file, ec))) {
    target = std::filesystem::weakly_canonical(file, ec);
    if (ec) throw InputError(file.string() + ": cannot follow the symbolic link");
  }
  const std::filesystem::file_status status = std::filesystem::status(target, ec);
  if (std::filesystem::is_directory(status)) throw InputError(file.string() + ": is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    return WriteToDevice(target, content);
  }
  WriteRegularFile(file, target, content);
}

void CheckOutputFile(const std::filesystem::path& file, const std::string& flag) {
  if (file == kStandardOutput || OwnDescriptor(file)) return;
  const std::string shown = flag + ": " + file.string();
  std::error_code ec;
  const std::filesystem::path target =
      std::filesystem::is_symlink(std::filesystem::symlink_status(file, ec))
          ? std::filesystem::weakly_canonical(file, ec)
          : file;
  const std::filesystem::file_status status = std::filesystem::status(target, ec);
  if (std::filesystem::is_directory(status)) throw InputError(shown + ": is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) return;
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(shown + ": cannot write: directory " + dir.string() + " does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw InputError(shown + ": cannot write: directory " + dir.string() + " is not writable");
  }
}

}  // namespace foresight
