#include "common/data_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/error.h"
#include "common/input_log.h"

namespace foresight {

void RequireDataFile(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) throw InputError(file.string() + ": cannot open file");
  if (std::filesystem::is_directory(status)) throw InputError(file.string() + ": is a directory");
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(file.string() + ": is not a regular file (a device or a pipe?)");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > max_bytes) {
    throw InputError(file.string() + ": " + std::to_string(size) + " bytes, more than the " +
                     std::to_string(max_bytes) + " a data file may have");
  }
}

std::string ReadDataFile(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  RequireDataFile(file, max_bytes);
  // O_NONBLOCK: a FIFO put in the file's place after the check does not block the open.
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw InputError(file.string() + ": cannot open file: " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      throw InputError(file.string() + ": cannot read file: " + std::strerror(error));
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {
      ::close(fd);
      throw InputError(file.string() + ": more than the " + std::to_string(max_bytes) +
                       " bytes a data file may have");
    }
  }
  ::close(fd);
  InputLog::Record(file);
  return text;
}

}  // namespace foresight
