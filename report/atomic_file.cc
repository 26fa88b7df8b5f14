#include "report/atomic_file.h"

#include <unistd.h>

#include <fstream>
#include <string>

#include "common/error.h"

namespace foresight {

void WriteFileAtomically(const std::filesystem::path& file, std::string_view content) {
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : ".";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(file.string() + ": cannot write: directory " + dir.string() +
                     " does not exist");
  }
  std::filesystem::path temp = file;
  temp += ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(file.string() + ": cannot write file");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();  // checked: a failed close can mean lost data
    if (!out) {
      std::filesystem::remove(temp, ec);
      throw InputError(file.string() + ": write failed");
    }
  }
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    throw InputError(file.string() + ": cannot move the finished file into place");
  }
}

}  // namespace foresight
