// How far a long loop is, as the command line prints it on standard error.
//
// On a terminal one line is rewritten in place ("\r") at every report. Into a log (Slurm, GNU
// parallel, a redirect) whole lines are written, at most one per `interval_s`, each with the
// rate and the time left, and a last one when the loop is done if any was written (a loop
// shorter than one interval writes nothing):
//   calibrate forward: 300 / 1000 trials (30 %), 61.2 trials/s, about 11 s left
// The clock is passed in so that tests need no real time.
#pragma once

#include <cstdio>
#include <functional>
#include <mutex>
#include <string>

namespace foresight {

// Seconds between lines in a log unless FORESIGHT_PROGRESS_INTERVAL_S says otherwise.
inline constexpr double kDefaultProgressIntervalS = 5.0;

struct ProgressLogSettings {
  bool terminal = false;                          // rewrite one line in place
  double interval_s = kDefaultProgressIntervalS;  // lines into a log: at most one per interval
  std::function<double()> clock_s;  // seconds, monotonic; empty: std::chrono::steady_clock
  std::FILE* out = stderr;
};

// The settings for standard error: a terminal or not (isatty), the interval from the
// environment variable FORESIGHT_PROGRESS_INTERVAL_S (seconds >= 0; an unreadable value is
// ignored: progress must never stop a run).
ProgressLogSettings StderrProgressSettings();

class ProgressLog {
 public:
  ProgressLog(std::string label, std::string unit, ProgressLogSettings settings);
  // A report: `done` of `total`. Thread-safe.
  void Report(int done, int total);
  // The text of one report at `elapsed_s` after the first (no "\r", no newline).
  static std::string Line(const std::string& label, const std::string& unit, int done, int total,
                          double elapsed_s);

 private:
  double Now() const;

  std::string label_, unit_;
  ProgressLogSettings settings_;
  std::mutex mutex_;
  double start_s_ = 0.0;
  double last_line_s_ = 0.0;
  bool printed_ = false;
};

}  // namespace foresight
