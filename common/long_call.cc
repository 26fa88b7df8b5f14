#include "common/long_call.h"

#include <algorithm>
#include <atomic>
#include <memory>

namespace foresight {

namespace {

thread_local LongCallHost* current_host = nullptr;
thread_local std::chrono::steady_clock::time_point last_poll{};
thread_local std::chrono::steady_clock::duration poll_every = kPollInterval;

}  // namespace

ScopedLongCallHost::ScopedLongCallHost(LongCallHost& host,
                                       std::chrono::steady_clock::duration poll_interval)
    : previous_(current_host), previous_poll_(last_poll), previous_interval_(poll_every) {
  current_host = &host;
  last_poll = std::chrono::steady_clock::now();
  poll_every = poll_interval;
}

ScopedLongCallHost::~ScopedLongCallHost() {
  current_host = previous_;
  last_poll = previous_poll_;
  poll_every = previous_interval_;
}

LongCallHost* CurrentLongCallHost() {
  return current_host;
}

void PollLongCall() {
  if (current_host == nullptr) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_poll < poll_every) return;
  last_poll = now;
  current_host->Poll();
}

ProgressFunction LongCallProgress(const std::string& label, const std::string& unit,
                                  ProgressFunction fallback) {
  LongCallHost* host = current_host;
  if (host == nullptr) return fallback;
  // The last step of kProgressSteps reported; shared by the copies of the reporter.
  auto reported = std::make_shared<std::atomic<long long>>(0);
  return [host, label, unit, reported](int done, int total) {
    const long long step =
        total > 0 ? static_cast<long long>(done) * kProgressSteps / total : kProgressSteps;
    long long last = reported->load(std::memory_order_relaxed);
    // A report per new step; the last item always (its step may have been reported already).
    while (step > last || done == total) {
      if (reported->compare_exchange_weak(last, std::max(step, last), std::memory_order_relaxed)) {
        host->Progress(label, done, total, unit);
        return;
      }
    }
  };
}

}  // namespace foresight
