// Ctrl-C waits while a result is put in place, then acts.
#include "report/signal_guard.h"

#include <gtest/gtest.h>

#include <csignal>

namespace foresight {
namespace {

volatile std::sig_atomic_t interrupted = 0;
void OnInterrupt(int) {
  interrupted = 1;
}

TEST(SignalGuardTest, AnInterruptDuringTheGuardActsWhenItEnds) {
  struct sigaction action = {}, previous = {};
  action.sa_handler = OnInterrupt;
  sigaction(SIGINT, &action, &previous);
  interrupted = 0;
  {
    const SignalGuard guard;
    raise(SIGINT);
    EXPECT_EQ(interrupted, 0) << "the signal acted inside the guard";
  }
  EXPECT_EQ(interrupted, 1) << "the held signal was lost";
  sigaction(SIGINT, &previous, nullptr);
}

}  // namespace
}  // namespace foresight
