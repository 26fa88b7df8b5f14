// Runs body(i) for i in [0, count) on `threads` threads. Work is handed out by index, and each
// index's result goes to its own slot, so results never depend on the thread count. The first
// exception thrown by a body stops the hand-out and is rethrown on the calling thread.
#pragma once

#include <functional>

namespace foresight {

// threads <= 0: all hardware threads. progress(done, count) is called from the calling thread's
// perspective under a lock, at most about 100 times.
void ParallelFor(int count, int threads, const std::function<void(int)>& body,
                 const std::function<void(int, int)>& progress = {});

int HardwareThreads();

}  // namespace foresight
