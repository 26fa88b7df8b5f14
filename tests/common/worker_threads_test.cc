#include "common/worker_threads.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <new>
#include <system_error>

namespace foresight {
namespace {

// A starter that starts `allowed` threads and then refuses like the system does when no thread
// or address space is left.
template <typename Refusal>
ThreadStarter Refusing(int allowed, std::atomic<int>& attempts) {
  return [allowed, &attempts](const std::function<void()>& work) {
    if (attempts++ >= allowed) throw Refusal();
    return std::thread(work);
  };
}

struct NoThreadLeft : std::system_error {
  NoThreadLeft() : std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again)) {}
};

TEST(WorkerThreadsTest, StartsTheThreadsAskedForAndJoinsThem) {
  std::atomic<int> ran{0};
  {
    WorkerThreads threads(3, [&] { ++ran; });
    EXPECT_EQ(threads.Started(), 3);
  }
  EXPECT_EQ(ran.load(), 3);
}

TEST(WorkerThreadsTest, AThreadTheSystemRefusesEndsTheStartingWithoutTerminating) {
  std::atomic<int> attempts{0}, ran{0};
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int kept_of_6 = std::min(3, cores);
  {
    // 6 start, the 7th is refused: the address space is full, so half step back, and all but
    // one per core.
    WorkerThreads threads(8, [&] { ++ran; }, Refusing<NoThreadLeft>(6, attempts));
    EXPECT_EQ(threads.Started(), kept_of_6);
  }
  EXPECT_EQ(ran.load(), kept_of_6);
  EXPECT_EQ(attempts.load(), 7);  // stops at the first refusal
}

TEST(WorkerThreadsTest, MemoryRefusedForAThreadIsTheSame) {
  std::atomic<int> attempts{0}, ran{0};
  {
    WorkerThreads threads(4, [&] { ++ran; }, Refusing<std::bad_alloc>(0, attempts));
    EXPECT_EQ(threads.Started(), 0);
  }
  EXPECT_EQ(ran.load(), 0);
}

TEST(WorkerThreadsTest, StartedThreadsAreJoinedWhileAnExceptionPasses) {
  std::atomic<int> attempts{0}, ran{0};
  EXPECT_THROW(
      {
        WorkerThreads threads(4, [&] { ++ran; }, Refusing<NoThreadLeft>(2, attempts));  // 1 kept
        throw std::runtime_error("the caller's own work failed");
      },
      std::runtime_error);
  EXPECT_EQ(ran.load(), 1);
}

TEST(WorkerThreadsTest, NoThreadWorksBeforeAllAreStarted) {
  std::atomic<int> starting{0};
  std::atomic<bool> worked_early{false};
  const ThreadStarter counting = [&](const std::function<void()>& work) {
    std::thread thread(work);
    ++starting;
    return thread;
  };
  {
    WorkerThreads threads(5, [&] { worked_early = worked_early || starting.load() < 5; }, counting);
  }
  EXPECT_FALSE(worked_early.load());
}

}  // namespace
}  // namespace foresight
