// Time integration to the periodic steady state (hbtrack simulate), from rest or from an HBM
// state of the same case.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/fold_search.hpp"
#include "hbtrack/runs/simulate.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "python_monitor.hpp"

namespace hbtrack::python {

namespace {

// start: optional HBM state [omega, x0, x1, ...] (a row of a result's states); omega <= 0 takes
// the start's frequency; progress(fraction of max_periods, period, time at its end).
py::dict simulate(const CaseDefinition& c, double omega, const std::optional<Eigen::VectorXd>& start, IntegrationMethod method,
                  int steps_per_period, int element_steps, const SteadyStateOptions& steady, const py::object& progress) {
  runs::SimulateOptions options;
  if (omega > 0) options.omega = omega;
  if (start) {
    if (start->size() < 1) throw CaseError("start: expected a state [omega, x0, x1, ...]");
    options.start = runs::StartPoint{(*start)(0), start->tail(start->size() - 1), "start"};
  }
  options.method = method;
  options.steps_per_period = steps_per_period;
  options.element_steps = element_steps;
  options.steady = steady;
  options.steps_name = "steps_per_period";
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::simulate(c, options, sink, monitor); });
}

// simulate(near_lp=K): the branch's states rows [omega, x0, ...], its stable flags and first
// output's first harmonic per row, its special_points; the runs as `simulate --near-lp`.
py::dict simulate_near_fold(const CaseDefinition& c, const Eigen::MatrixXd& states, const std::vector<bool>& stable,
                            const Eigen::VectorXd& amplitude, const py::handle& special_points, long k,
                            const std::vector<double>& distances, IntegrationMethod method, int steps_per_period, int element_steps,
                            const SteadyStateOptions& steady, const py::object& progress) {
  const nlohmann::json points = from_python(special_points);
  const nlohmann::json& lp = points[runs::special_point_index(points, SpecialPointType::limit_point, k, {"near_lp", "start"})];
  if (static_cast<Eigen::Index>(stable.size()) != states.rows() || amplitude.size() != states.rows() || states.cols() < 2)
    throw CaseError("start: its states, stable flags and amplitudes must have one row per point");
  std::vector<runs::FoldSearchRow> rows;
  for (Eigen::Index i = 0; i < states.rows(); ++i) rows.push_back({states(i, 0), stable[static_cast<size_t>(i)], amplitude(i)});
  runs::FoldSearchOptions o;
  o.simulate.method = method;
  o.simulate.steps_per_period = steps_per_period;
  o.simulate.element_steps = element_steps;
  o.simulate.steady = steady;
  o.simulate.steps_name = "steps_per_period";
  o.lp = static_cast<int>(k);
  o.lp_omega = lp.value("omega", 0.0);
  o.candidates = runs::fold_search_rows(rows, lp.value("index", 0L), o.lp_omega, distances, "start");
  o.start_at = [&](long row) {
    return runs::StartPoint{states(row, 0), states.row(row).tail(states.cols() - 1).transpose(), "start: point " + std::to_string(row)};
  };
  o.origin = {{"near_lp", k}};
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::simulate_near_fold(c, o, sink, monitor); });
}

}  // namespace

void bind_timeint(py::module_& m) {
  m.def("simulate", &simulate, py::arg("case"), py::arg("omega"), py::arg("start"), py::arg("method"), py::arg("steps_per_period"),
        py::arg("element_steps"), py::arg("steady"), py::arg("progress") = py::none(),
        "time integration to the periodic steady state: {signals, summary}");
  m.def("simulate_near_fold", &simulate_near_fold, py::arg("case"), py::arg("states"), py::arg("stable"), py::arg("amplitude"),
        py::arg("special_points"), py::arg("k"), py::arg("distances"), py::arg("method"), py::arg("steps_per_period"),
        py::arg("element_steps"), py::arg("steady"), py::arg("progress") = py::none(),
        "time integrations next to limit point k until one holds the orbit: {summary, branches}");
}

}  // namespace hbtrack::python
