// Long calls that can be stopped and that say how far they are: the one hook between the long
// loops (trials, experiments, fits) and whoever runs them.
//
// A host that wants to stop a running call or hear its progress (the Python module: Ctrl-C and
// a progress callback; a test) installs a LongCallHost for the calling thread with
// ScopedLongCallHost. Long loops call PollLongCall() between items: ParallelFor does on the
// thread that called it, after each of its items; loops that run long items on one thread
// (a match, a physics trial's steps) poll inside. PollLongCall() calls the host's Poll() at most
// every kPollInterval, so a loop may poll per item whatever an item costs; Poll() stops the call
// by throwing (the Python module throws the KeyboardInterrupt that Python's signal handler
// recorded). Without a host a poll costs one thread-local load. Other threads (ParallelFor's
// helpers) have no host: the calling thread's exception stops the hand-out, so a call ends
// within one item per thread after the host says stop.
//
// Progress: the commands make their progress reporters with LongCallProgress(label, unit, or);
// with a host on the calling thread, the reports go to its Progress() (from any thread: the
// host must lock what it needs), at most kProgressSteps of them per loop, otherwise to `or` (the
// command line's printer, common/progress_log.h). Loops report every item; the limit is here.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace foresight {

class LongCallHost {
 public:
  virtual ~LongCallHost() = default;
  // Throws to stop the call. Called on the thread that installed the host.
  virtual void Poll() = 0;
  // `done` of `total` `unit` of the part `label` ("calibrate forward", "trials"). May be called
  // from any thread of the call, one at a time per loop.
  virtual void Progress(const std::string& label, int done, int total, const std::string& unit) = 0;
};

// Host polls at most this often: Ctrl-C is seen within a fraction of a second, and a poll that
// takes the GIL costs nothing measurable against the 20 ms between polls.
inline constexpr std::chrono::milliseconds kPollInterval{20};

// Installs `host` for the calling thread until the end of the scope (the previous one, if any,
// comes back); its Poll() is called at most every `poll_interval` (tests pass 0: every poll).
class ScopedLongCallHost {
 public:
  explicit ScopedLongCallHost(LongCallHost& host,
                              std::chrono::steady_clock::duration poll_interval = kPollInterval);
  ~ScopedLongCallHost();
  ScopedLongCallHost(const ScopedLongCallHost&) = delete;
  ScopedLongCallHost& operator=(const ScopedLongCallHost&) = delete;

 private:
  LongCallHost* previous_;
  std::chrono::steady_clock::time_point previous_poll_;
  std::chrono::steady_clock::duration previous_interval_;
};

// The calling thread's host, or nullptr.
LongCallHost* CurrentLongCallHost();

// Calls the calling thread's host's Poll() if its poll interval has passed since the last time;
// nothing without a host.
void PollLongCall();

using ProgressFunction = std::function<void(int done, int total)>;

// A host hears at most this many progress reports per loop (plus the last item's), whatever the
// loop's length: a host's Progress() may be costly (the Python module takes the GIL for it), and
// a loop may report every item.
inline constexpr int kProgressSteps = 100;

// A progress reporter for one loop: to the calling thread's host if it has one, rate-limited to
// one report each time another 1/kProgressSteps of the total is done and one for the last item;
// otherwise `fallback` (which may be empty: no report; it limits its own rate,
// common/progress_log.h).
ProgressFunction LongCallProgress(const std::string& label, const std::string& unit,
                                  ProgressFunction fallback);

}  // namespace foresight
