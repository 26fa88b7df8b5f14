// Runs body(i) for i in [0, count) on `threads` threads. Work is handed out by index, and each
// index's result goes to its own slot, so results never depend on the thread count. The first
// exception thrown by a body (or by progress) stops the hand-out and is rethrown on the calling
// thread once every thread has stopped. A thread the system refuses to start (no threads or
// address space left, common/worker_threads.h) is no error: the run goes on with the threads
// that started, down to the calling thread alone. Neither is a thread that runs out of memory
// (std::bad_alloc: under an address-space limit every thread's stack and heap count): it stops,
// and its index runs again after the other threads are done, on the calling thread, where
// running out of memory is the caller's error. So body(i) must be safe to run twice (each index
// writes only its own slot). The calling thread polls its long-call host (common/long_call.h)
// after each of its items, so a host's exception (Ctrl-C) stops the hand-out like a body's.
#pragma once

#include <functional>

#include "common/worker_threads.h"

namespace foresight {

// threads <= 0: all hardware threads. progress(done, count) is called under a lock, at most
// about 100 times. `start` starts the helper threads (tests pass one that refuses some).
void ParallelFor(int count, int threads, const std::function<void(int)>& body,
                 const std::function<void(int, int)>& progress = {},
                 const ThreadStarter& start = StartThread);

int HardwareThreads();

}  // namespace foresight
