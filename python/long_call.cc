#include "python/long_call.h"

namespace py = pybind11;

namespace foresight::python {

PythonLongCall::PythonLongCall(py::object progress) : progress_(std::move(progress)) {
  if (!progress_.is_none() && !PyCallable_Check(progress_.ptr())) {
    throw py::type_error("progress: must be None or a callable (label, done, total)");
  }
}

void PythonLongCall::Poll() {
  py::gil_scoped_acquire gil;
  // Runs the handlers of signals that arrived (Python's own SIGINT handler raises
  // KeyboardInterrupt); only the main thread runs them, so a call from another thread is not
  // stopped by Ctrl-C, as with Python's own blocking calls.
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

void PythonLongCall::Progress(const std::string& label, int done, int total,
                              const std::string& /*unit*/) {
  if (progress_.is_none()) return;
  py::gil_scoped_acquire gil;
  progress_(label, done, total);
}

}  // namespace foresight::python
