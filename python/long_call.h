// Python's side of common/long_call.h: a long call runs without the GIL, polls Python's signal
// handlers (Ctrl-C becomes KeyboardInterrupt within kPollInterval plus one item per thread) and
// hands its progress to an optional callback progress(label, done, total). Every long function
// of the module runs its work through RunLongCall; nothing else in the module deals with
// signals.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "common/long_call.h"

namespace foresight::python {

class PythonLongCall : public LongCallHost {
 public:
  // `progress`: None or a callable (label: str, done: int, total: int). Made with the GIL.
  explicit PythonLongCall(pybind11::object progress);
  // Takes the GIL; a pending signal whose handler raises (KeyboardInterrupt) is thrown as
  // pybind11::error_already_set, which the module boundary gives back to Python.
  void Poll() override;
  // Takes the GIL and calls the callback; its exception stops the call the same way.
  void Progress(const std::string& label, int done, int total, const std::string& unit) override;

 private:
  pybind11::object progress_;
};

// Runs `work` without the GIL with a PythonLongCall installed for this thread.
template <typename Work>
auto RunLongCall(const pybind11::object& progress, Work&& work) {
  PythonLongCall host(progress);
  ScopedLongCallHost installed(host);
  pybind11::gil_scoped_release release;
  return std::forward<Work>(work)();
}

}  // namespace foresight::python
