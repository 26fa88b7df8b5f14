#include "common/parallel_for.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <new>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace foresight {
namespace {

// Starts `allowed` threads, then refuses as the system does when no thread or address space is
// left (`ulimit -v`).
ThreadStarter RefuseAfter(int allowed) {
  auto started = std::make_shared<std::atomic<int>>(0);
  return [allowed, started](const std::function<void()>& work) {
    if ((*started)++ >= allowed) {
      throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
    }
    return std::thread(work);
  };
}

std::vector<long long> Squares(int count, int threads, const ThreadStarter& start) {
  std::vector<long long> slots(count, -1);
  ParallelFor(count, threads, [&](int i) { slots[i] = 1LL * i * i; }, {}, start);
  return slots;
}

TEST(ParallelForTest, EveryIndexRunsOnceWhateverTheThreadCount) {
  const std::vector<long long> one = Squares(1000, 1, StartThread);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(one[i], 1LL * i * i);
  EXPECT_EQ(Squares(1000, 7, StartThread), one);
}

TEST(ParallelForTest, ThreadsTheSystemRefusesLeaveTheSameResults) {
  const std::vector<long long> all = Squares(500, 4, StartThread);
  EXPECT_EQ(Squares(500, 200, RefuseAfter(3)), all);
  EXPECT_EQ(Squares(500, 200, RefuseAfter(0)), all);  // the calling thread alone
}

TEST(ParallelForTest, ABodysExceptionReachesTheCallerFromAnyThread) {
  for (const int allowed : {0, 5}) {
    try {
      ParallelFor(
          100, 8,
          [](int i) {
            if (i == 37) throw std::runtime_error("index 37 failed");
          },
          {}, RefuseAfter(allowed));
      ADD_FAILURE() << "nothing was thrown";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "index 37 failed");
    }
  }
}

TEST(ParallelForTest, AnIndexWhoseThreadRanOutOfMemoryRunsAgain) {
  // Every helper thread runs out of memory on its first index, as threads do under `ulimit -v`
  // when the others hold the memory; the calling thread does the rest and those indices again.
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::atomic<int>> attempts(300);
  std::vector<int> slots(300, -1);
  ParallelFor(300, 4, [&](int i) {
    if (attempts[i]++ == 0 && std::this_thread::get_id() != caller) throw std::bad_alloc();
    slots[i] = i;
  });
  int again = 0;
  for (int i = 0; i < 300; ++i) {
    ASSERT_EQ(slots[i], i);
    ASSERT_LE(attempts[i].load(), 2);
    again += attempts[i].load() - 1;
  }
  EXPECT_LE(again, 3);  // at most one index per helper
}

TEST(ParallelForTest, OutOfMemoryOnTheCallingThreadAloneReachesTheCaller) {
  EXPECT_THROW(ParallelFor(100, 4,
                           [](int i) {
                             if (i == 42) throw std::bad_alloc();
                           }),
               std::bad_alloc);
}

TEST(ParallelForTest, AProgressCallbacksExceptionReachesTheCaller) {
  EXPECT_THROW(ParallelFor(
                   100, 4, [](int) {}, [](int, int) { throw std::runtime_error("progress"); }),
               std::runtime_error);
}

TEST(ParallelForTest, ProgressEndsAtTheCount) {
  int last = 0;
  ParallelFor(
      250, 3, [](int) {}, [&](int done, int count) {
        EXPECT_EQ(count, 250);
        last = std::max(last, done);
      });
  EXPECT_EQ(last, 250);
}

}  // namespace
}  // namespace foresight
