// Branch switching at a BP or PD of an NFRC: the computation of `hbtrack switch`, with the same
// tables and summary fields (the branch in one piece: the leg back through the point reversed,
// then the leg away from it). The assembly repeats apps/hbtrack/verb_switch.cpp's; one function
// for both belongs in the runs layer (issue 16), which is being built beside this.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "gil_release.hpp"
#include "progress_callback.hpp"
#include "hbtrack/analysis/branch_switching.hpp"
#include "hbtrack/analysis/period_doubling.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::python {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

HarmonicBalance system_of(const CaseDefinition& c) {
  try {
    return HarmonicBalance(c.model, c.elements, c.parameters, c.harmonic_balance);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
}

// type: "BP" or "PD"; (omega, x) the point; before/after its neighbours on the NFRC.
// progress(fraction, point, omega): each of the two legs counts for half, by the part of the
// omega range between the point and the end the leg heads for that it has covered.
py::dict switch_branch(const CaseDefinition& period_one, const std::string& type, int point, double omega, const Eigen::VectorXd& x,
                       double omega_before, const Eigen::VectorXd& x_before, double omega_after, const Eigen::VectorXd& x_after,
                       const py::object& progress) {
  const auto t0 = Clock::now();
  HarmonicBalance hbm = system_of(period_one);
  if (x.size() != hbm.unknowns() || x_before.size() != hbm.unknowns() || x_after.size() != hbm.unknowns())
    throw CaseError("start: its states hold " + std::to_string(x.size()) + " unknowns, the case has " + std::to_string(hbm.unknowns()) +
                    " (a result of another case?)");
  CaseDefinition c = period_one;
  if (type == "PD") c.harmonic_balance = period_doubled_options(period_one.harmonic_balance);  // the branch at omega / 2
  HarmonicBalance system = system_of(c);
  Eigen::VectorXd known(hbm.unknowns() + 1);
  known.head(hbm.unknowns()) = x_after - x_before;
  known(hbm.unknowns()) = omega_after - omega_before;
  json summary = {{"verb", "switch"}, {"options", options_json(c, system)}};
  summary["options"]["switch"] = {{"point", point}, {"type", type}, {"omega", omega}};
  SwitchedBranch s;
  ProgressCallback callback(progress);
  const double lo = std::min(c.nfrc.omega_start, c.nfrc.omega_end), hi = std::max(c.nfrc.omega_start, c.nfrc.omega_end);
  int legs_started = 0, reported = 0;
  Coverage coverage = Coverage::one_way(omega, omega);
  const RecordedObserver observer = [&](const BranchPoint& p, const RecordedPoint&, int index) {
    if (index == 0) {  // a new leg, its direction not known yet
      ++legs_started;
      coverage = Coverage::one_way(omega, omega);
    }
    if (index == 1) coverage = Coverage::one_way(omega, p.lambda > omega ? hi : lo);  // the leg's direction
    return callback(0.5 * (std::min(legs_started, 2) - 1 + coverage.add(p.lambda)), reported++, p.lambda);
  };
  {
    GilRelease release;
    s = type == "PD" ? switch_at_period_doubling(system, hbm.basis(), c.nfrc, c.outputs, x, omega, known, observer)
                     : switch_at_branch_point(system, c.nfrc, c.outputs, x, omega, known, true, false, observer);
  }
  callback.rethrow();
  Table branch{branch_header(c), {}}, states{state_header(system.unknowns()), {}}, special{state_header(system.unknowns()), {}};
  Table dof_states{dof_state_header(system), {}}, dof_special{dof_state_header(system), {}};  // as states.csv, special_states.csv
  const auto add_point = [&](const RecordedPoint& recorded, const BranchPoint& p) {
    branch.rows.push_back(branch_row(recorded));
    states.rows.push_back(state_row(p.lambda, p.u));
    dof_states.rows.push_back(dof_state_row(system, p.lambda, p.u));
  };
  const int through = static_cast<int>(s.through.recorded.size());
  for (int i = through - 1; i >= 0; --i) add_point(s.through.recorded[static_cast<size_t>(i)], s.through.continuation.points[static_cast<size_t>(i)]);
  const int shift = through > 0 ? through - 1 : 0;  // row of the away leg's point i: shift + i
  for (size_t i = through > 0 ? 1 : 0; i < s.away.recorded.size(); ++i) add_point(s.away.recorded[i], s.away.continuation.points[i]);
  json points = json::array();
  for (const auto* leg : {&s.through, &s.away})
    for (const auto& p : leg->continuation.special_points) {
      json j = {{"type", p.type},
                {"index", leg == &s.through ? through - 1 - p.index : shift + p.index},
                {"omega", p.lambda},
                {"located", p.located}};
      j["parameters"] = summary["options"]["parameters"];
      add_outputs(j, c, record_point(system, p.u, p.lambda, c.outputs));
      points.push_back(j);
      special.rows.push_back(state_row(p.lambda, p.u));
      dof_special.rows.push_back(dof_state_row(system, p.lambda, p.u));
    }
  const auto& a = s.away.continuation.summary;
  const auto& b = s.through.continuation.summary;
  summary["special_points"] = points;
  summary["outputs"] = outputs_json(c);
  summary["points"] = shift + static_cast<int>(s.away.recorded.size());
  summary["legs"] = {{{"name", "through"}, {"stop_reason", to_string(b.stop_reason)}, {"points", b.points}},
                     {{"name", "away"}, {"stop_reason", to_string(a.stop_reason)}, {"points", a.points}}};
  // A period-doubled leg ends where it rejoins the period-T branch (at a PD of the band).
  const bool away_ok = s.away.continuation.success() || a.stop_reason == StopReason::rejoined;
  const bool ok = away_ok && (s.through.continuation.success() || b.stop_reason == StopReason::rejoined);
  summary["stop_reason"] = to_string(ok ? StopReason::completed : (away_ok ? b.stop_reason : a.stop_reason));
  summary["timings"] = {{"wall_s", std::chrono::duration<double>(Clock::now() - t0).count()}};
  py::dict out;
  out["branch"] = branch.columns();
  out["states"] = states.matrix();
  out["special_states"] = special.matrix();
  out["dof_states"] = dof_states.columns();
  out["dof_special_states"] = dof_special.columns();
  out["summary"] = to_python(summary);
  out["special_points"] = out["summary"]["special_points"];
  callback.mark(out);
  return out;
}

}  // namespace

void bind_switch(py::module_& m) {
  m.def("switch", &switch_branch, py::arg("case"), py::arg("type"), py::arg("point"), py::arg("omega"), py::arg("x"),
        py::arg("omega_before"), py::arg("x_before"), py::arg("omega_after"), py::arg("x_after"),
        py::arg("progress") = py::none(), "the branch through a BP, or the period-doubled branch of a PD: {branch, states, dof_states, special_points, special_states, dof_special_states, summary}");
}

}  // namespace hbtrack::python
