#include "report/temporary_name.h"

#include <unistd.h>

#include <atomic>

namespace foresight {

std::string UniqueSuffix() {
  static std::atomic<unsigned long> count{0};
  return std::to_string(::getpid()) + "." + std::to_string(++count);
}

}  // namespace foresight
