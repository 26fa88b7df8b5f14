#include "common/input_log.h"

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace foresight {

namespace {

struct Log {
  std::mutex mutex;
  bool open = false;
  std::vector<std::filesystem::path> read, allowed;
};

Log& TheLog() {
  static Log log;
  return log;
}

// One spelling per file, so that the same file read twice is one entry and "a/../b" is "b".
std::filesystem::path Key(const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::path key = std::filesystem::weakly_canonical(file, ec);
  return ec ? std::filesystem::absolute(file, ec).lexically_normal() : key;
}

bool Contains(const std::vector<std::filesystem::path>& files, const std::filesystem::path& key) {
  return std::find(files.begin(), files.end(), key) != files.end();
}

}  // namespace

InputLog::InputLog() {
  Log& log = TheLog();
  const std::lock_guard lock(log.mutex);
  if (log.open) throw std::logic_error("InputLog: a log is already open");
  log.open = true;
  log.read.clear();
  log.allowed.clear();
}

InputLog::~InputLog() {
  Log& log = TheLog();
  const std::lock_guard lock(log.mutex);
  log.open = false;
  log.read.clear();
  log.allowed.clear();
}

void InputLog::Record(const std::filesystem::path& file) {
  Log& log = TheLog();
  const std::lock_guard lock(log.mutex);
  if (!log.open) return;
  const std::filesystem::path key = Key(file);
  if (!Contains(log.read, key)) log.read.push_back(key);
}

void InputLog::Allow(const std::filesystem::path& file) {
  Log& log = TheLog();
  const std::lock_guard lock(log.mutex);
  if (!log.open || file.empty()) return;
  log.allowed.push_back(Key(file));
}

std::vector<std::filesystem::path> InputLog::Files() {
  Log& log = TheLog();
  const std::lock_guard lock(log.mutex);
  std::vector<std::filesystem::path> files;
  for (const std::filesystem::path& key : log.read) {
    if (!Contains(log.allowed, key)) files.push_back(key);
  }
  return files;
}

}  // namespace foresight
