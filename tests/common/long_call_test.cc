#include "common/long_call.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/parallel_for.h"

namespace foresight {
namespace {

struct Stop : std::runtime_error {
  Stop() : std::runtime_error("stop") {}
};

// A host that says stop at its `stop_at`-th poll and records the progress it hears.
class TestHost : public LongCallHost {
 public:
  explicit TestHost(int stop_at) : stop_at_(stop_at) {}
  void Poll() override {
    if (++polls == stop_at_) throw Stop();
  }
  void Progress(const std::string& label, int done, int total, const std::string& unit) override {
    heard.push_back(label + " " + std::to_string(done) + "/" + std::to_string(total) + " " + unit);
  }
  std::atomic<int> polls{0};  // read by helper threads in one test
  std::vector<std::string> heard;

 private:
  int stop_at_;
};

TEST(LongCallTest, WithoutAHostAPollDoesNothing) {
  EXPECT_EQ(CurrentLongCallHost(), nullptr);
  PollLongCall();  // no host: nothing to call, nothing thrown
}

TEST(LongCallTest, TheHostStopsAParallelLoopOnTheCallingThread) {
  for (const int threads : {1, 3}) {
    TestHost host(5);
    ScopedLongCallHost installed(host, std::chrono::nanoseconds(0));
    const std::thread::id caller = std::this_thread::get_id();
    int on_caller = 0;
    // A helper's item lasts until the host has said stop, so the calling thread reaches its
    // fifth item however the threads are scheduled (on a loaded machine the helpers could
    // otherwise take all 10000 items before the calling thread takes its first).
    const auto item = [&](int) {
      if (std::this_thread::get_id() == caller) {
        ++on_caller;
        return;
      }
      while (host.polls.load() < 5) std::this_thread::yield();
    };
    EXPECT_THROW(ParallelFor(10000, threads, item), Stop) << threads;
    // Stopped after the calling thread's fifth item, polled after each of its items. (How many
    // items the helpers finish between the stop and the end of the hand-out depends on the
    // scheduler; ParallelForTest checks that an exception ends the hand-out.)
    EXPECT_EQ(host.polls.load(), 5) << threads;
    EXPECT_EQ(on_caller, 5) << threads;
  }
}

TEST(LongCallTest, HelperThreadsNeverPoll) {
  TestHost host(0);  // never stops
  ScopedLongCallHost installed(host, std::chrono::nanoseconds(0));
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> on_helpers{0};
  ParallelFor(400, 4, [&](int) {
    if (std::this_thread::get_id() != caller) {
      PollLongCall();  // a helper has no host: nothing happens
      ++on_helpers;
    }
  });
  // Only the calling thread's own items polled (one poll each, inside ParallelFor).
  EXPECT_EQ(host.polls.load(), 400 - on_helpers.load());
}

TEST(LongCallTest, PollsAreSpacedByTheInterval) {
  TestHost host(0);
  ScopedLongCallHost installed(host, std::chrono::hours(1));
  for (int i = 0; i < 1000; ++i) PollLongCall();
  EXPECT_EQ(host.polls.load(), 0);  // an hour has not passed
}

TEST(LongCallTest, ScopesNestAndRestore) {
  TestHost outer(0), inner(0);
  {
    ScopedLongCallHost a(outer);
    EXPECT_EQ(CurrentLongCallHost(), &outer);
    {
      ScopedLongCallHost b(inner);
      EXPECT_EQ(CurrentLongCallHost(), &inner);
    }
    EXPECT_EQ(CurrentLongCallHost(), &outer);
  }
  EXPECT_EQ(CurrentLongCallHost(), nullptr);
}

TEST(LongCallTest, ProgressGoesToTheHostOrElseTheFallback) {
  int fallback_calls = 0;
  const auto fallback = [&](int, int) { ++fallback_calls; };
  LongCallProgress("simulate", "trials", fallback)(1, 2);
  EXPECT_EQ(fallback_calls, 1);
  TestHost host(0);
  ScopedLongCallHost installed(host);
  const ProgressFunction report = LongCallProgress("simulate", "trials", fallback);
  ParallelFor(
      4, 2, [](int) {}, report);
  EXPECT_EQ(fallback_calls, 1);
  ASSERT_FALSE(host.heard.empty());
  EXPECT_EQ(host.heard.back(), "simulate 4/4 trials");
}

// Every long call is rate-limited in one place: a loop that reports each of a million items
// reaches the host (the Python module takes the GIL per report) about kProgressSteps times,
// in order, ending with the last item.
TEST(LongCallTest, TheHostHearsAtMostOneReportPerStepAndTheLast) {
  TestHost host(0);
  ScopedLongCallHost installed(host);
  const ProgressFunction report = LongCallProgress("decide", "poses", {});
  constexpr int kItems = 1000000;
  for (int done = 1; done <= kItems; ++done) report(done, kItems);
  EXPECT_LE(host.heard.size(), static_cast<std::size_t>(kProgressSteps + 1));
  EXPECT_GE(host.heard.size(), static_cast<std::size_t>(kProgressSteps));
  EXPECT_EQ(host.heard.front(), "decide 10000/1000000 poses");
  EXPECT_EQ(host.heard.back(), "decide 1000000/1000000 poses");
  // A short loop still reports every item.
  host.heard.clear();
  const ProgressFunction few = LongCallProgress("simulate", "trials", {});
  for (int done = 1; done <= 3; ++done) few(done, 3);
  EXPECT_EQ(host.heard.size(), 3u);
}

}  // namespace
}  // namespace foresight
