#pragma once
// The `progress` callback of the Python runs: progress(fraction, point, value) after every
// accepted point, fraction the part of the run's range covered (hbtrack::Coverage, as the CLI's
// progress line), value the run's own variable (omega, the parameter, the time). Returning False
// stops the run (stop_reason "stopped_by_callback"); an exception stops it and is re-raised.
#include <optional>

#include "bindings.hpp"

namespace hbtrack::python {

class ProgressCallback {
 public:
  explicit ProgressCallback(py::object callback) : callback_(std::move(callback)) {}
  // Called with the GIL released, from a run's observer: false when the run must stop (Ctrl-C,
  // the callback returned False or raised).
  bool operator()(double fraction, int point, double value);
  // With the GIL held, after the run: re-raises Ctrl-C or the callback's exception.
  void rethrow();
  // out["summary"]["stop_reason"] = "stopped_by_callback" when the callback stopped the run.
  void mark(py::dict& out) const;

 private:
  py::object callback_;
  bool interrupted_ = false, stopped_ = false, bad_answer_ = false;
  std::optional<py::error_already_set> error_;
};

}  // namespace hbtrack::python
