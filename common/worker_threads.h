// A group of threads that all run the same function and are always joined, and that survives
// a system which refuses to start some of them.
//
// std::thread throws std::system_error when the system has no thread or address space left (an
// address-space limit such as `ulimit -v`, or a Slurm job's, reaches it after a few dozen
// threads: each stack reserves megabytes), and a std::thread destroyed while joinable ends the
// process with std::terminate. WorkerThreads therefore starts threads one by one and stops at the
// first one refused (std::system_error or std::bad_alloc). The started threads wait until the
// starting is over; after a refusal the address space is full of stacks, so half of them, and
// all beyond one per core, leave without working (their stacks are freed) and the others have
// room for their work. Every
// thread is joined when the group ends, also while an exception passes. Fewer threads is not an
// error: the callers' results never depend on the thread count (common/parallel_for.h).
#pragma once

#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace foresight {

// Starts one thread running `work`, or throws as std::thread's constructor does.
using ThreadStarter = std::function<std::thread(const std::function<void()>& work)>;

// The ordinary starter: a std::thread.
std::thread StartThread(const std::function<void()>& work);

class WorkerThreads {
 public:
  // Starts up to `count` threads running `work` (which must not throw: catch inside it); returns
  // once they run.
  WorkerThreads(int count, const std::function<void()>& work,
                const ThreadStarter& start = StartThread);
  ~WorkerThreads();  // joins every started thread
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;

  // How many threads run `work` (0 .. count; after a refusal at most half of those that started).
  int Started() const { return static_cast<int>(threads_.size()); }
  // Waits for every started thread to finish.
  void JoinAll();

 private:
  struct Gate;
  void Signal(const std::function<void()>& change);

  std::shared_ptr<Gate> gate_;
  std::vector<std::thread> threads_;
};

}  // namespace foresight
