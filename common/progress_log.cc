#include "common/progress_log.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace foresight {

namespace {

std::string Duration(double s) {
  char text[32];
  if (s < 120.0) {
    std::snprintf(text, sizeof text, "%.0f s", s);
  } else if (s < 7200.0) {
    std::snprintf(text, sizeof text, "%.0f min", s / 60.0);
  } else {
    std::snprintf(text, sizeof text, "%.1f h", s / 3600.0);
  }
  return text;
}

double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ProgressLogSettings StderrProgressSettings() {
  ProgressLogSettings settings;
  settings.terminal = isatty(STDERR_FILENO) != 0;
  if (const char* env = std::getenv("FORESIGHT_PROGRESS_INTERVAL_S"); env != nullptr) {
    char* end = nullptr;
    const double value = std::strtod(env, &end);
    if (end != env && *end == '\0' && std::isfinite(value) && value >= 0.0) {
      settings.interval_s = value;
    }
  }
  return settings;
}

ProgressLog::ProgressLog(std::string label, std::string unit, ProgressLogSettings settings)
    : label_(std::move(label)), unit_(std::move(unit)), settings_(std::move(settings)) {
  start_s_ = Now();
  last_line_s_ = start_s_;
}

double ProgressLog::Now() const {
  return settings_.clock_s ? settings_.clock_s() : SteadySeconds();
}

std::string ProgressLog::Line(const std::string& label, const std::string& unit, int done,
                              int total, double elapsed_s) {
  char text[160];
  const double percent = total > 0 ? 100.0 * done / total : 100.0;
  int n = std::snprintf(text, sizeof text, "%d / %d %s (%.0f %%)", done, total, unit.c_str(),
                        std::floor(percent));
  std::string line = label + ": " + std::string(text, static_cast<std::size_t>(n));
  if (done >= total) return line + ", done in " + Duration(elapsed_s);
  if (done > 0 && elapsed_s > 0.0) {
    const double rate = done / elapsed_s;
    n = std::snprintf(text, sizeof text, ", %.3g %s/s, about ", rate, unit.c_str());
    line +=
        std::string(text, static_cast<std::size_t>(n)) + Duration((total - done) / rate) + " left";
  }
  return line;
}

void ProgressLog::Report(int done, int total) {
  std::lock_guard<std::mutex> lock(mutex_);
  const double now = Now();
  const bool last = done >= total;
  if (settings_.terminal) {
    std::fprintf(settings_.out, "\r%s", Line(label_, unit_, done, total, now - start_s_).c_str());
    if (last) std::fprintf(settings_.out, "\n");
    std::fflush(settings_.out);
    return;
  }
  // A loop shorter than one interval stays silent; one that printed says when it is done.
  if (last ? !printed_ && settings_.interval_s > 0.0 : now - last_line_s_ < settings_.interval_s) {
    return;
  }
  last_line_s_ = now;
  printed_ = true;
  std::fprintf(settings_.out, "%s\n", Line(label_, unit_, done, total, now - start_s_).c_str());
  std::fflush(settings_.out);
}

}  // namespace foresight
