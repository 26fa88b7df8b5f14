#include "common/worker_threads.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <system_error>

namespace foresight {

std::thread StartThread(const std::function<void()>& work) {
  return std::thread(work);
}

// Threads wait here until every thread is started, so that none of them allocates while threads
// are still being started; those told to step back leave without working, the others work once
// those are gone.
struct WorkerThreads::Gate {
  std::mutex mutex;
  std::condition_variable changed;
  int leave_from = std::numeric_limits<int>::max();  // threads numbered this or above leave
  bool go = false;
};

WorkerThreads::WorkerThreads(int count, const std::function<void()>& work,
                             const ThreadStarter& start)
    : gate_(std::make_shared<Gate>()) {
  bool refused = false;
  for (int t = 0; t < count && !refused; ++t) {
    const std::function<void()> wait_then_work = [gate = gate_, t, work] {
      {
        std::unique_lock<std::mutex> lock(gate->mutex);
        gate->changed.wait(lock, [&] { return gate->go || t >= gate->leave_from; });
        if (t >= gate->leave_from) return;
      }
      // The C++ runtime's thread-local exception state is allocated on first use; in a library
      // loaded at run time (the Python module) failing to allocate it aborts the process, so it
      // is allocated now, while there is room, not on the first std::bad_alloc.
      static_cast<void>(std::uncaught_exceptions());
      work();
    };
    try {
      // Room for the handle first, so that a thread once started is always owned (and joined).
      threads_.reserve(threads_.size() + 1);
      threads_.push_back(start(wait_then_work));
    } catch (const std::system_error&) {
      refused = true;  // no thread or address space left
    } catch (const std::bad_alloc&) {
      refused = true;
    }
  }
  // A refusal means the address space is full of stacks: half of the started threads, and all
  // beyond one per core, step back (their stacks are freed when they are joined) so that the
  // others have room for their work (and for the C library's per-thread heaps).
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int keep = refused ? std::min(Started() / 2, cores) : Started();
  Signal([&] { gate_->leave_from = keep; });
  for (int t = Started() - 1; t >= keep; --t) {
    threads_[static_cast<std::size_t>(t)].join();
    threads_.pop_back();
  }
  Signal([&] { gate_->go = true; });
}

void WorkerThreads::Signal(const std::function<void()>& change) {
  {
    std::lock_guard<std::mutex> lock(gate_->mutex);
    change();
  }
  gate_->changed.notify_all();
}

WorkerThreads::~WorkerThreads() {
  JoinAll();
}

void WorkerThreads::JoinAll() {
  for (std::thread& thread : threads_) {
    if (thread.joinable()) thread.join();
  }
}

}  // namespace foresight
