// Time integration to the periodic steady state (hbtrack simulate), from rest or from an HBM
// state of the same case.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/simulate.hpp"
#include "python_monitor.hpp"

namespace hbtrack::python {

namespace {

// start: optional HBM state [omega, x0, x1, ...] (a row of a result's states); omega <= 0 takes
// the start's frequency; progress(fraction of max_periods, period, time at its end).
py::dict simulate(const CaseDefinition& c, double omega, const std::optional<Eigen::VectorXd>& start, IntegrationMethod method,
                  int steps_per_period, const SteadyStateOptions& steady, const py::object& progress) {
  runs::SimulateOptions options;
  if (omega > 0) options.omega = omega;
  if (start) {
    if (start->size() < 1) throw CaseError("start: expected a state [omega, x0, x1, ...]");
    options.start = runs::StartPoint{(*start)(0), start->tail(start->size() - 1), "start"};
  }
  options.method = method;
  options.steps_per_period = steps_per_period;
  options.steady = steady;
  options.steps_name = "steps_per_period";
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::simulate(c, options, sink, monitor); });
}

}  // namespace

void bind_timeint(py::module_& m) {
  m.def("simulate", &simulate, py::arg("case"), py::arg("omega"), py::arg("start"), py::arg("method"), py::arg("steps_per_period"),
        py::arg("steady"), py::arg("progress") = py::none(), "time integration to the periodic steady state: {signals, summary}");
}

}  // namespace hbtrack::python
