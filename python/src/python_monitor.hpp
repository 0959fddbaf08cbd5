#pragma once
// A run's monitor in Python (runs/run_monitor.hpp): the progress callback after every point and
// Ctrl-C (progress_callback.hpp), and the runs computed with the GIL released into tables in
// memory, returned as dicts with the keys hbtrack.read_result gives for the CLI's folder.
#include <optional>

#include "bindings.hpp"
#include "gil_release.hpp"
#include "hbtrack/runs/memory_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "progress_callback.hpp"

namespace hbtrack::python {

class PythonMonitor final : public runs::RunMonitor {
 public:
  explicit PythonMonitor(py::object progress) : callback_(std::move(progress)) {}
  // progress(fraction, point, value): the run's range covered, the point, its variable.
  bool point(const runs::PointProgress& p) override { return callback_(p.fraction, p.index, p.value); }
  // progress(fraction of the period budget, period, time at its end).
  bool period(int period, double, double time, double fraction) override { return callback_(fraction, period, time); }
  ProgressCallback& callback() { return callback_; }

 private:
  ProgressCallback callback_;
};

// A run's tables as the Python functions return them: every table as {column: 1-D array} under
// its name, but "states" and "special_states" (every dof's harmonics, as the CSV files) under
// "dof_states" and "dof_special_states", and the raw unknowns ("unknowns", "special_unknowns")
// as 2-D arrays under "states" and "special_states" (what later runs start from); "summary",
// "special_points" when the summary lists them, and the results inside (the branches of
// isolas) under "branches".
py::dict result_dict(const runs::MemorySink& sink);

// run(sink, monitor) -> RunReport with the GIL released; re-raises what stopped it by error
// (Ctrl-C, the progress callback's exception), marks a stop asked by the callback
// ("stopped_by_callback") and returns result_dict of the sink.
template <class Run>
py::dict run_in_memory(const py::object& progress, Run run) {
  runs::MemorySink sink;
  PythonMonitor monitor(progress);
  {
    GilRelease release;
    run(sink, monitor);
  }
  monitor.callback().rethrow();
  py::dict out = result_dict(sink);
  monitor.callback().mark(out);
  return out;
}

}  // namespace hbtrack::python
