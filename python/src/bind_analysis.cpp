// NFRC, solve, modes, limit-point tracking and isolas: the runs of hbtrack frc / solve / modes /
// track / isolas (src/runs/), into tables in memory, computed with the GIL released.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/runs/campbell.hpp"
#include "hbtrack/runs/frc.hpp"
#include "hbtrack/runs/isolas.hpp"
#include "hbtrack/runs/modes.hpp"
#include "hbtrack/runs/torus.hpp"
#include "hbtrack/runs/track.hpp"
#include "python_monitor.hpp"

namespace hbtrack::python {

namespace {

using runs::make_system;

// The NFRC over the case's range; with `start` (the unknowns at omega_start, a point of another
// result) from that point towards omega_end, as `hbtrack frc --from`.
py::dict frc(const CaseDefinition& c, const py::object& progress, const std::optional<Eigen::VectorXd>& start, bool element_forces) {
  runs::FrcOptions options;
  options.element_forces = element_forces;
  if (start) options.start = runs::StartPoint{c.nfrc.omega_start, *start, "start"};
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::frc(c, options, sink, monitor); });
}

// `hbtrack solve`: one periodic solution at omega.
py::dict solve(const CaseDefinition& c, double omega) {
  return run_in_memory(py::none(), [&](runs::ResultSink& sink, runs::RunMonitor&) { runs::solve(c, omega, sink); });
}

// `hbtrack modes`: the summary of the lowest `count` natural frequencies; a failure raises.
py::dict modes(const CaseDefinition& c, int count) {
  runs::RunReport report;
  py::dict out = run_in_memory(py::none(), [&](runs::ResultSink& sink, runs::RunMonitor&) { report = runs::modes(c, count, sink); });
  if (!report.success()) throw std::runtime_error("modes: " + report.failure);
  return out;
}

// `hbtrack modes --speeds`: the Campbell diagram of a rotating case; a failure raises.
py::dict campbell(const CaseDefinition& c, const std::vector<double>& speeds, int count, const std::vector<std::string>& names,
                  int engine_orders) {
  runs::CampbellOptions options;
  options.speeds = speeds;
  options.count = count;
  options.names = names;
  options.engine_orders = engine_orders;
  runs::RunReport report;
  py::dict out = run_in_memory(py::none(), [&](runs::ResultSink& sink, runs::RunMonitor&) { report = runs::campbell(c, options, sink); });
  if (!report.success()) throw std::runtime_error("campbell: " + report.failure);
  return out;
}

// `hbtrack track` from a limit point (point LP; NS, PD: a Neimark-Sacker or
// period-doubling point) (x, omega) of an NFRC of the same case.
py::dict track(const CaseDefinition& c, const Eigen::VectorXd& x, double omega, const std::string& param, double parameter_min,
               double parameter_max, TrackingMethod method, const py::object& progress, const std::string& point) {
  runs::TrackOptions options;
  options.tracked = parse_tracked_point(point, "point");
  options.parameter = param;
  options.parameter_min = parameter_min;
  options.parameter_max = parameter_max;
  options.method = method;
  options.start = runs::StartPoint{omega, x, "start: the " + point + " point"};
  options.range_name = "range";
  options.parameter_name = "param";
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::track(c, options, sink, monitor); });
}

// `hbtrack torus` from the NS point (x, omega) of an NFRC of the same case.
py::dict torus(const CaseDefinition& c, const Eigen::VectorXd& x, double omega, double omega_min, double omega_max, int h1, int h2, int n1,
               int n2, const py::object& progress) {
  runs::TorusRunOptions options;
  options.start = runs::StartPoint{omega, x, "start: the NS point"};
  options.omega_min = omega_min;
  options.omega_max = omega_max;
  options.h1 = h1;
  options.h2 = h2;
  options.n1 = n1;
  options.n2 = n2;
  options.range_name = "range";
  options.harmonics_name = "harmonics";
  options.samples_name = "samples";
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::torus(c, options, sink, monitor); });
}

// Tracking curves as `track` returns their states: rows of leg, omega, parameter, x0, x1, ...
std::vector<FoldCurvePoint> curve_from_states(const Eigen::MatrixXd& states, int unknowns) {
  if (states.cols() != 3 + unknowns)
    throw CaseError("curves: a tracking curve's states hold " + std::to_string(states.cols() - 3) + " unknowns, the case has " +
                    std::to_string(unknowns) + " (a result of another case?)");
  std::vector<FoldCurvePoint> curve;
  for (Eigen::Index i = 0; i < states.rows(); ++i) {
    FoldCurvePoint p;
    p.leg = static_cast<int>(states(i, 0));
    p.omega = states(i, 1);
    p.parameter = states(i, 2);
    p.x = states.row(i).tail(unknowns).transpose();
    curve.push_back(std::move(p));
  }
  return curve;
}

// `hbtrack isolas`: every crossing of the curves with param = at, and the branch through each
// new limit point; isola_K / open_K entries under "branches" as the CLI's folders.
py::dict isolas(const CaseDefinition& c, const std::vector<Eigen::MatrixXd>& curve_states, const std::string& param, double at,
                const py::object& progress) {
  runs::IsolaOptions options;
  options.parameter = param;
  options.at = at;
  const int unknowns = make_system(c).unknowns();
  for (const auto& states : curve_states) options.curves.push_back(curve_from_states(states, unknowns));
  py::dict out =
      run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::isolas(c, options, sink, monitor); });
  if (!out.contains("branches")) out["branches"] = py::dict();  // none found
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("frc", &frc, py::arg("case"), py::arg("progress") = py::none(), py::arg("start") = py::none(), py::arg("element_forces") = false,
        "NFRC with stability: {branch, states, dof_states, stability, special_points, special_states, dof_special_states, summary}"
        " and element_forces when asked");
  m.def("solve", &solve, py::arg("case"), py::arg("omega"), "one periodic solution at omega: {branch, states, dof_states, summary}");
  m.def("modes", &modes, py::arg("case"), py::arg("count") = 10, "the lowest natural frequencies of the case's model: {summary}");
  m.def("campbell", &campbell, py::arg("case"), py::arg("speeds"), py::arg("count") = 6, py::arg("names") = std::vector<std::string>{},
        py::arg("engine_orders") = 8, "the Campbell diagram of a case with [rotation]: {campbell, summary}");
  m.def("track", &track, py::arg("case"), py::arg("x"), py::arg("omega"), py::arg("param"), py::arg("parameter_min"),
        py::arg("parameter_max"), py::arg("method") = "bordered", py::arg("progress") = py::none(),
        py::arg("point") = to_string(SpecialPointType::limit_point), "limit point (NS, PD point) (x, omega) tracked in param");
  m.def("torus", &torus, py::arg("case"), py::arg("x"), py::arg("omega"), py::arg("omega_min"), py::arg("omega_max"), py::arg("h1") = 0,
        py::arg("h2") = 4, py::arg("n1") = 0, py::arg("n2") = 0, py::arg("progress") = py::none(),
        "the torus branch born at the NS point (x, omega), continued in omega within [omega_min, omega_max]");
  m.def("isolas", &isolas, py::arg("case"), py::arg("curves"), py::arg("param"), py::arg("at"), py::arg("progress") = py::none(),
        "branches through the crossings of tracking curves (their states) with param = at");
}

}  // namespace hbtrack::python
