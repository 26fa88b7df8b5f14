#include "common/long_call.h"

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
  return [host, label, unit](int done, int total) { host->Progress(label, done, total, unit); };
}

}  // namespace foresight
