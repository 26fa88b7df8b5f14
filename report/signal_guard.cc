#include "report/signal_guard.h"

#include <pthread.h>

namespace foresight {

SignalGuard::SignalGuard() {
  sigset_t held;
  sigemptyset(&held);
  sigaddset(&held, SIGINT);
  sigaddset(&held, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &held, &previous_);
}

SignalGuard::~SignalGuard() {
  pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

}  // namespace foresight
