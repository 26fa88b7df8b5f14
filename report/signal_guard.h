// Holding back Ctrl-C while a result is put in place. SIGINT and SIGTERM end a run at
// once by default, which is what a user wants during the work: nothing has been written yet. The
// only moment a signal could leave a temporary file or folder behind is the short write that puts
// the finished result in place; a SignalGuard blocks both signals for that moment (in the calling
// thread, which is the only one running then) and lets a pending one act when it ends, after the
// result is whole.
#pragma once

#include <signal.h>

namespace foresight {

class SignalGuard {
 public:
  SignalGuard();
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

 private:
  sigset_t previous_;
};

}  // namespace foresight
