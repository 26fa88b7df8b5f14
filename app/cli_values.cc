#include "app/cli_values.h"

#include <charconv>
#include <filesystem>
#include <memory>

#include "common/checks.h"
#include "common/error.h"
#include "common/long_call.h"
#include "common/progress_log.h"
#include "report/output_set.h"

namespace foresight {

namespace {

template <typename T>
bool ParseWhole(const std::string& text, T& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && !text.empty();
}

}  // namespace

int ParseCount(const std::string& flag, const std::string& text, int lo, int hi) {
  long long value = 0;
  if (!ParseWhole(text, value) || value < lo || value > hi) {
    throw InputError(flag + ": must be an integer in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "], got '" + text + "'");
  }
  return static_cast<int>(value);
}

std::uint64_t ParseSeed(const std::string& text) {
  std::uint64_t value = 0;
  if (!ParseWhole(text, value)) {
    throw InputError("--seed: must be an integer in [0, 18446744073709551615], got '" + text + "'");
  }
  return value;
}

double ParseNumber(const std::string& flag, const std::string& text, double lo, double hi) {
  double value = 0.0;
  if (!ParseWhole(text, value) || !(value >= lo && value <= hi)) {
    throw InputError(flag + ": must be a number in [" + FormatNumber(lo) + ", " + FormatNumber(hi) +
                     "], got '" + text + "'");
  }
  return value;
}

std::function<void(int, int)> CommandProgress(const std::string& label, const std::string& unit) {
  auto log = std::make_shared<ProgressLog>(label, unit, StderrProgressSettings());
  return LongCallProgress(label, unit, [log](int done, int total) { log->Report(done, total); });
}

std::vector<ReportFile> ReportFolderFiles(const ReportFiles& files) {
  std::vector<ReportFile> named;
  for (const auto& [file, content] : files) named.push_back({file.filename().string(), content});
  return named;
}

OutputSet ReportFolderOutput(const std::string& dir) {
  OutputSet outputs;
  outputs.AddFolder("--out", dir);
  return outputs;
}

std::optional<bool> ParseSwitch(const std::string& flag, const std::string& text) {
  if (text.empty()) return std::nullopt;
  if (text == "on") return true;
  if (text == "off") return false;
  throw InputError(flag + ": must be on or off, got '" + text + "'");
}

}  // namespace foresight
