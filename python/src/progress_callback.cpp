#include "progress_callback.hpp"

#include <algorithm>

#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack::python {

bool ProgressCallback::operator()(double fraction, int point, double value) {
  if (interrupted_ || stopped_ || error_ || bad_answer_) return false;  // the next leg or branch stops at once too
  if ((interrupted_ = python_interrupted())) return false;
  if (callback_.is_none()) return true;
  py::gil_scoped_acquire acquire;
  try {
    const py::object answer = callback_(std::clamp(fraction, 0.0, 1.0), point, value);
    stopped_ = !answer.is_none() && !answer.cast<bool>();
  } catch (py::error_already_set& e) {
    error_.emplace(std::move(e));
  } catch (const py::cast_error&) {
    bad_answer_ = true;
  }
  return !stopped_ && !error_ && !bad_answer_;
}

void ProgressCallback::rethrow() {
  if (interrupted_) throw py::error_already_set();
  if (error_) throw *error_;
  if (bad_answer_) throw py::value_error("progress: must return None, True or False");
}

void ProgressCallback::mark(py::dict& out) const {
  if (stopped_) out["summary"]["stop_reason"] = to_string(StopReason::stopped_by_callback);
}

}  // namespace hbtrack::python
