// NFRC, limit-point tracking and isolas: the computations of hbtrack frc / track / isolas, with
// the same tables (as columns) and summary fields, computed with the GIL released.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "gil_release.hpp"
#include "progress_callback.hpp"
#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/element_force_table.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::python {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The case's harmonic balance system; a model the case reader let through but the system
// rejects is bad input (ValueError naming the case).
HarmonicBalance make_system(const CaseDefinition& c) {
  try {
    return HarmonicBalance(c.model, c.elements, c.parameters, c.harmonic_balance);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
}

// A branch as `frc` writes it: branch.csv columns, the unknowns of each point (states), the
// summary's special points with their states; every dof's harmonics as states.csv and
// special_states.csv hold them (dof_states, dof_special_states); element_forces.csv on request.
py::dict branch_result(const CaseDefinition& c, HarmonicBalance& hbm, const NfrcResult& r, json summary, bool element_forces = false) {
  Table branch{branch_header(c), {}}, states{state_header(hbm.unknowns()), {}}, special{state_header(hbm.unknowns()), {}};
  Table dof_states{dof_state_header(hbm), {}}, dof_special{dof_state_header(hbm), {}}, forces{element_force_header(hbm), {}};
  for (size_t i = 0; i < r.recorded.size(); ++i) {
    const BranchPoint& p = r.continuation.points[i];
    branch.rows.push_back(branch_row(r.recorded[i]));
    states.rows.push_back(state_row(p.lambda, p.u));
    dof_states.rows.push_back(dof_state_row(hbm, p.lambda, p.u));
    if (element_forces) forces.rows.push_back(element_force_row(hbm, p.lambda, p.u));
  }
  for (const auto& sp : r.continuation.special_points) {
    special.rows.push_back(state_row(sp.lambda, sp.u));
    dof_special.rows.push_back(dof_state_row(hbm, sp.lambda, sp.u));
  }
  add_nfrc_summary(summary, c, hbm, r);
  py::dict out;
  if (c.nfrc.stability.enabled()) {  // stability.csv: the Floquet exponents of every point
    Table stability{stability_header(), {}};
    for (size_t i = 0; i < r.recorded.size(); ++i)
      for (auto& row : stability_rows(static_cast<int>(i), r.recorded[i])) stability.rows.push_back(std::move(row));
    out["stability"] = stability.columns();
  }
  out["branch"] = branch.columns();
  out["states"] = states.matrix();
  out["special_states"] = special.matrix();
  out["dof_states"] = dof_states.columns();
  out["dof_special_states"] = dof_special.columns();
  if (element_forces) out["element_forces"] = forces.columns();
  out["summary"] = to_python(summary);
  out["special_points"] = out["summary"]["special_points"];
  return out;
}

// The NFRC over the case's range; with `start` (the unknowns at omega_start, a point of another
// result) from that point towards omega_end, as `hbtrack frc --from`.
py::dict frc(const CaseDefinition& c, const py::object& progress, const std::optional<Eigen::VectorXd>& start, bool element_forces) {
  const auto t0 = Clock::now();
  HarmonicBalance hbm = make_system(c);
  if (start && start->size() != hbm.unknowns())
    throw CaseError("start: holds " + std::to_string(start->size()) + " unknowns, the case's harmonic balance has " +
                    std::to_string(hbm.unknowns()) + " (a result of another case?)");
  json summary = {{"verb", "frc"}, {"options", options_json(c, hbm)}};
  ProgressCallback callback(progress);
  Coverage coverage = Coverage::one_way(c.nfrc.omega_start, c.nfrc.omega_end);
  const RecordedObserver observer = [&](const BranchPoint& p, const RecordedPoint&, int index) {
    return callback(coverage.add(p.lambda), index, p.lambda);
  };
  NfrcResult r;
  {
    GilRelease release;
    if (!start) {
      r = compute_nfrc(hbm, c.nfrc, c.outputs, observer);
    } else {
      const double from = c.nfrc.omega_start, end = c.nfrc.omega_end;
      r = compute_branch(hbm, c.nfrc, c.outputs, *start, from, ParameterWindow{std::min(from, end), std::max(from, end), end > from ? 1 : -1, false},
                         observer);
    }
  }
  callback.rethrow();
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", r.continuation.summary.wall_s}, {"stability_s", r.stability_s}};
  py::dict out = branch_result(c, hbm, r, summary, element_forces);
  callback.mark(out);
  return out;
}

// `hbtrack track` from a limit point (x, omega) of an NFRC of the same case.
py::dict track(const CaseDefinition& c, const Eigen::VectorXd& x, double omega, const std::string& param, double parameter_min,
               double parameter_max, const std::string& method, const py::object& progress) {
  const auto t0 = Clock::now();
  FoldTrackingOptions tracking;
  tracking.parameter_min = parameter_min;
  tracking.parameter_max = parameter_max;
  tracking.continuation = c.nfrc.continuation;
  if (!(parameter_min < parameter_max)) throw CaseError("range: must be (LO, HI) with LO < HI");
  tracking.method = parse_choice<TrackingMethod>(method, "method");  // a ValueError as the CaseErrors
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), param, "param");
  const double start_value = hbm.parameters().value(parameter);
  if (!(parameter_min <= start_value && start_value <= parameter_max))
    throw CaseError("range: must contain " + param + " = " + std::to_string(start_value) + " of the limit point");
  if (x.size() != hbm.unknowns())
    throw CaseError("start: the limit point holds " + std::to_string(x.size()) + " unknowns, the case has " + std::to_string(hbm.unknowns()) +
                    " (a result of another case?)");

  Table branch{tracking_header(c, param), {}}, states{{"leg", "omega", param}, {}};
  for (const std::string& column : state_header(hbm.unknowns())) if (column != "omega") states.header.push_back(column);
  Table dof_states{{"leg", "omega", param}, {}};
  for (const std::string& column : dof_state_columns(hbm)) dof_states.header.push_back(column);
  json summary = {{"verb", "track"}, {"options", options_json(c, hbm)}};
  summary["options"]["tracking"] = {{"parameter", param}, {"method", method}, {"range", {parameter_min, parameter_max}}};
  const FoldScales scales = tracking_scales(hbm, c.nfrc, parameter_max - parameter_min);
  FoldTrackingResult r;
  ProgressCallback callback(progress);
  Coverage coverage = Coverage::two_legs(parameter_min, parameter_max, start_value);  // as the CLI's line
  {
    GilRelease release;
    r = track_fold(hbm, parameter, x, omega, scales, tracking, c.outputs, [&](const FoldCurvePoint& p, int) {
      branch.rows.push_back(tracking_row(p));
      std::vector<double> row{static_cast<double>(p.leg), p.omega, p.parameter};
      row.insert(row.end(), p.x.data(), p.x.data() + p.x.size());
      states.rows.push_back(row);
      std::vector<double> dofs{static_cast<double>(p.leg), p.omega, p.parameter};
      for (double value : dof_state_values(hbm, p.x, p.omega, parameter, p.parameter)) dofs.push_back(value);
      dof_states.rows.push_back(std::move(dofs));
      return callback(coverage.add(p.parameter, p.leg), static_cast<int>(states.rows.size()) - 1, p.parameter);
    });
  }
  callback.rethrow();
  add_tracking_summary(summary, c, r, param);
  summary["start"] = {{"omega", omega}, {param, start_value}};
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  py::dict out;
  out["branch"] = branch.columns();
  out["states"] = states.matrix();
  out["dof_states"] = dof_states.columns();
  out["summary"] = to_python(summary);
  out["special_points"] = out["summary"]["special_points"];
  callback.mark(out);
  return out;
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
// new limit point; isola_K / open_K entries as the CLI's folders.
py::dict isolas(const CaseDefinition& c, const std::vector<Eigen::MatrixXd>& curve_states, const std::string& param, double at,
                const py::object& progress) {
  const auto t0 = Clock::now();
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), param, "param");
  std::vector<std::vector<FoldCurvePoint>> curves;
  for (const auto& states : curve_states) curves.push_back(curve_from_states(states, hbm.unknowns()));
  double lo = at, hi = at;
  for (const auto& curve : curves)
    for (const auto& p : curve) lo = std::min(lo, p.parameter), hi = std::max(hi, p.parameter);
  hbm.set_parameter(parameter, at);
  const FoldScales scales = tracking_scales(hbm, c.nfrc, std::max(hi - lo, 1e-300));
  std::vector<IsolaCandidate> found;
  // Per branch, the part of the omega range its points span (an isola closes within it); the
  // point counts on across the branches.
  ProgressCallback callback(progress);
  const double omega_lo = std::min(c.nfrc.omega_start, c.nfrc.omega_end), omega_hi = std::max(c.nfrc.omega_start, c.nfrc.omega_end);
  double low = 0, high = 0;
  int point = 0;
  const RecordedObserver observer = [&](const BranchPoint& p, const RecordedPoint&, int index) {
    if (index == 0) low = high = p.lambda;
    low = std::min(low, p.lambda), high = std::max(high, p.lambda);
    return callback(covered_fraction(omega_lo + high - low, omega_lo, omega_hi), point++, p.lambda);
  };
  {
    GilRelease release;
    found = compute_isolas(hbm, parameter, at, curves, scales, c.nfrc, c.outputs, true, observer);
  }
  callback.rethrow();
  json crossings = json::array();
  py::dict branches;
  int isola_count = 0;
  for (size_t k = 0; k < found.size(); ++k) {
    const IsolaCandidate& f = found[k];
    json j = {{"status", f.status}, {"omega", f.start.omega}, {"converged", f.start.converged}};
    if (f.same_as >= 0) j["same_as"] = f.same_as;
    if (f.status == "isola" || f.status == "open") {
      const std::string name = f.status == "isola" ? "isola_" + std::to_string(++isola_count) : "open_" + std::to_string(k + 1);
      hbm.set_parameter(parameter, at);
      json branch_summary = {{"verb", "isolas"}, {"options", options_json(c, hbm)}};
      py::dict branch = branch_result(c, hbm, f.branch, branch_summary);
      branches[py::str(name)] = branch;
      j["folder"] = name;
      j["stop_reason"] = f.branch.continuation.summary.stop_reason;
      j["points"] = f.branch.continuation.summary.points;
      double omega_min = 1e300, omega_max = -1e300;
      for (const auto& p : f.branch.continuation.points) omega_min = std::min(omega_min, p.lambda), omega_max = std::max(omega_max, p.lambda);
      j["omega_range"] = {omega_min, omega_max};
      int unstable = 0;
      for (const auto& rec : f.branch.recorded) unstable += rec.stable == 0;
      j["unstable_points"] = unstable;
    }
    crossings.push_back(j);
  }
  json summary = {{"verb", "isolas"}, {"options", options_json(c, hbm)}, {"stop_reason", "completed"}, {"crossings", crossings},
                  {"isolas", isola_count}, {"timings", {{"wall_s", seconds_since(t0)}}}};
  summary["options"]["isolas"] = {{"parameter", param}, {"at", at}};
  py::dict out;
  out["summary"] = to_python(summary);
  out["branches"] = branches;
  callback.mark(out);
  return out;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("frc", &frc, py::arg("case"), py::arg("progress") = py::none(), py::arg("start") = py::none(), py::arg("element_forces") = false,
        "NFRC with stability: {branch, states, dof_states, stability, special_points, special_states, dof_special_states, summary}"
        " and element_forces when asked");
  m.def("track", &track, py::arg("case"), py::arg("x"), py::arg("omega"), py::arg("param"), py::arg("parameter_min"),
        py::arg("parameter_max"), py::arg("method") = "bordered", py::arg("progress") = py::none(), "limit point (x, omega) tracked in param");
  m.def("isolas", &isolas, py::arg("case"), py::arg("curves"), py::arg("param"), py::arg("at"), py::arg("progress") = py::none(),
        "branches through the crossings of tracking curves (their states) with param = at");
}

}  // namespace hbtrack::python
