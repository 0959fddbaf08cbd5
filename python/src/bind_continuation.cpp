// Continuation in a named parameter at fixed omega and nonlinear modes (backbones): the
// computations of hbtrack continue / backbone, with the same tables and summary fields.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "gil_release.hpp"
#include "progress_callback.hpp"
#include "hbtrack/analysis/backbone.hpp"
#include "hbtrack/analysis/parameter_continuation.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/backbone_tables.hpp"
#include "hbtrack/results/parameter_tables.hpp"
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

// progress(fraction of [start, end] covered, point, the parameter's value).
py::dict continuation(const CaseDefinition& c, const std::string& param, double omega, double start, double end, const py::object& progress) {
  const auto t0 = Clock::now();
  if (!(omega > 0) || !std::isfinite(omega)) throw CaseError("omega: must be > 0 and finite");
  if (!std::isfinite(start) || !std::isfinite(end) || start == end) throw CaseError("range: must be (LO, HI), finite, LO != HI");
  HarmonicBalance hbm = system_of(c);
  const int parameter = parameter_index(hbm.parameters(), param, "param");
  json summary = {{"verb", "continue"}, {"options", options_json(c, hbm)}};
  summary["options"]["continue"] = parameter_continuation_options(param, omega, start, end);
  const double nominal = hbm.parameters().value(parameter);
  ParameterBranchResult r;
  ProgressCallback callback(progress);
  Coverage coverage = Coverage::one_way(start, end);
  {
    GilRelease release;
    r = continue_in_parameter(hbm, parameter, omega, start, end, c.nfrc, c.outputs, [&](const BranchPoint&, const ParameterBranchPoint& p, int index) {
      return callback(coverage.add(p.parameter), index, p.parameter);
    });
  }
  callback.rethrow();
  hbm.set_parameter(parameter, nominal);
  Table branch{parameter_branch_header(c, param), {}}, states{state_header(hbm.unknowns()), {}}, special{state_header(hbm.unknowns()), {}};
  Table dof_states{dof_state_header(hbm), {}}, dof_special{dof_state_header(hbm), {}};  // as states.csv, special_states.csv
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BranchPoint& p = r.continuation.points[i];
    branch.rows.push_back(parameter_branch_row(r.points[i]));
    states.rows.push_back(state_row(omega, p.u));
    dof_states.rows.push_back(dof_state_row(hbm, omega, p.u, parameter, p.lambda));
  }
  for (const auto& sp : r.continuation.special_points) {
    special.rows.push_back(state_row(omega, sp.u));
    dof_special.rows.push_back(dof_state_row(hbm, omega, sp.u, parameter, sp.lambda));
  }
  add_parameter_branch_summary(summary, c, hbm, r, parameter);
  summary["timings"] = {{"wall_s", std::chrono::duration<double>(Clock::now() - t0).count()}, {"continuation_s", r.continuation.summary.wall_s}};
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

// `hbtrack backbone`: the case with every dof as unknown (the CLI's override), mode from 1;
// progress(fraction of [log start, log end] covered, point, the modal amplitude).
py::dict backbone(CaseDefinition c, int mode, double start, double end, const py::object& progress) {
  const auto t0 = Clock::now();
  c.harmonic_balance.condensation = Condensation::none;
  HarmonicBalance hbm = system_of(c);
  BackboneOptions options;
  options.mode = mode;
  options.amplitude_start = start;
  options.amplitude_end = end;
  options.continuation = c.nfrc.continuation;
  json summary = {{"verb", "backbone"}, {"options", options_json(c, hbm)}};
  summary["options"]["backbone"] = backbone_options_json(options);
  BackboneResult r;
  ProgressCallback callback(progress);
  Coverage coverage = Coverage::one_way(std::log10(start), std::log10(end));  // the continuation steps in log10(a)
  {
    GilRelease release;
    r = compute_backbone(hbm, options, c.outputs, [&](const BranchPoint& p, const BackbonePoint& b, int index) {
      return callback(coverage.add(p.lambda), index, b.amplitude);
    });
  }
  callback.rethrow();
  Table branch{backbone_header(c, hbm.basis().harmonic_numbers()), {}}, states{backbone_state_header(hbm.unknowns()), {}};
  Table dof_states{dof_state_header(hbm), {}};  // as states.csv: the physical motion, a times the mode's unknowns
  for (size_t i = 0; i < r.points.size(); ++i) {
    const BackbonePoint& p = r.points[i];
    branch.rows.push_back(backbone_row(p));
    states.rows.push_back(backbone_state_row(p, r.continuation.points[i].u, hbm.unknowns()));
    dof_states.rows.push_back(dof_state_row(hbm, p.omega, p.amplitude * r.continuation.points[i].u.head(hbm.unknowns())));
  }
  add_backbone_summary(summary, c, hbm, r);
  summary["timings"] = {{"wall_s", std::chrono::duration<double>(Clock::now() - t0).count()}, {"continuation_s", r.continuation.summary.wall_s}};
  py::dict out;
  out["branch"] = branch.columns();
  out["states"] = states.matrix();
  out["dof_states"] = dof_states.columns();
  out["summary"] = to_python(summary);
  out["special_points"] = out["summary"]["special_points"];
  callback.mark(out);
  return out;
}

}  // namespace

void bind_continuation(py::module_& m) {
  m.def("continuation", &continuation, py::arg("case"), py::arg("param"), py::arg("omega"), py::arg("start"), py::arg("end"),
        py::arg("progress") = py::none(), "continuation in a named parameter at fixed omega: {branch, states, dof_states, special_points, special_states, dof_special_states, summary}");
  m.def("backbone", &backbone, py::arg("case"), py::arg("mode"), py::arg("start"), py::arg("end"), py::arg("progress") = py::none(),
        "nonlinear mode (EPMC) from the linear mode: {branch, states, dof_states, special_points, summary}");
}

}  // namespace hbtrack::python
