#include "common/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <new>
#include <thread>
#include <vector>

#include "common/long_call.h"

namespace foresight {

int HardwareThreads() {
  return std::max(1u, std::thread::hardware_concurrency());
}

void ParallelFor(int count, int threads, const std::function<void(int)>& body,
                 const std::function<void(int, int)>& progress, const ThreadStarter& start) {
  if (count <= 0) return;
  const int workers = std::clamp(threads <= 0 ? HardwareThreads() : threads, 1, count);
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  std::vector<int> out_of_memory;  // indices whose thread ran out of memory, to run again
  out_of_memory.reserve(static_cast<std::size_t>(workers));  // one per thread at most: no
                                                             // allocation when memory is gone
  int done = 0;
  const int report_every = std::max(1, count / 100);
  const auto finished = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress && (done % report_every == 0 || done == count)) progress(done, count);
  };
  const auto fail = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    if (!error) error = std::current_exception();
    failed = true;
  };
  // Never lets an exception out: a worker thread's exception would end the process. A thread
  // that runs out of memory (an address-space limit: every thread's stack and heap count) stops
  // and leaves its index to be run again once the other threads are done.
  const std::function<void()> work = [&] {
    try {
      for (int i = next++; i < count && !failed; i = next++) {
        try {
          body(i);
        } catch (const std::bad_alloc&) {  // the body's, not progress's: run it again later
          std::lock_guard<std::mutex> lock(mutex);
          out_of_memory.push_back(i);
          return;
        }
        finished();
        PollLongCall();  // the calling thread's host (Ctrl-C); helper threads have none
      }
    } catch (...) {
      fail();
    }
  };
  if (workers == 1) {  // no thread to start: the loop itself, exceptions to the caller
    for (int i = 0; i < count; ++i) {
      body(i);
      finished();
      PollLongCall();
    }
    return;
  }
  {
    WorkerThreads helpers(workers - 1, work, start);
    work();
  }  // joins the helpers
  // What threads left undone when memory ran out: on this thread alone, in index order; running
  // out of memory here is the caller's error.
  std::sort(out_of_memory.begin(), out_of_memory.end());
  try {
    for (const int i : out_of_memory) {
      if (failed) break;
      body(i);
      finished();
      PollLongCall();
    }
    for (int i = next++; i < count && !failed; i = next++) {
      body(i);
      finished();
      PollLongCall();
    }
  } catch (...) {
    fail();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace foresight
