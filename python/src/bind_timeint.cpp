// Time integration to the periodic steady state (hbtrack simulate), from rest or from an HBM
// state of the same case.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "bindings.hpp"
#include "gil_release.hpp"
#include "progress_callback.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"

namespace hbtrack::python {

namespace {

using nlohmann::json;

// start: optional HBM state [omega, x0, x1, ...] (a row of a result's states); omega <= 0 takes
// the start's frequency. progress(fraction of max_periods, period, time at its end).
py::dict simulate(const CaseDefinition& c, double omega, const std::optional<Eigen::VectorXd>& start, IntegrationMethod method,
                  int steps_per_period, const SteadyStateOptions& steady_options, const py::object& progress) {
  SteadyStateOptions steady = steady_options;
  steady.harmonics = c.harmonic_balance.harmonics;
  steady.validate();
  if (steps_per_period < 2 * steady.harmonics + 1)
    throw CaseError("steps_per_period: must be >= 2*harmonics+1 = " + std::to_string(2 * steady.harmonics + 1) + ", got " +
                    std::to_string(steps_per_period));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const int n = c.model.dofs();
  MotionState initial = rest_state(n);
  json summary = {{"verb", "simulate"}, {"options", options_json(c, hbm)}};
  if (start) {
    if (start->size() != 1 + hbm.unknowns())
      throw CaseError("start: holds " + std::to_string(start->size() - 1) + " unknowns after omega, the case has " +
                      std::to_string(hbm.unknowns()) + " (a result of another case?)");
    const double start_omega = (*start)(0);
    if (!(start_omega > 0)) throw CaseError("start: omega must be > 0");
    const Eigen::VectorXd x = start->tail(hbm.unknowns());
    if (!(omega > 0)) omega = start_omega;
    const Eigen::VectorXd full = hbm.expand(x, start_omega);
    initial = state_from_harmonics(full, n, steady.harmonics, hbm.fundamental(start_omega));  // harmonics of omega / nu
    json j = {{"omega", start_omega}};
    add_outputs(j, c, record_point(hbm, x, start_omega, c.outputs));
    for (const OutputDof& out : c.outputs) {
      const Eigen::VectorXd h = dof_harmonics(full, n, steady.harmonics, out.dof);
      j["harmonics_" + out.name] = std::vector<double>(h.data(), h.data() + h.size());
    }
    summary["start"] = j;
  }
  if (!(omega > 0)) throw CaseError("omega: must be > 0 (or give a start state)");
  EquationOfMotion equation(c.model, c.elements, hbm.parameters(), omega);
  std::unique_ptr<TimeIntegrator> integrator;
  json integrator_settings;  // as the CLI records them
  if (method == IntegrationMethod::newmark) {
    NewmarkOptions no;
    no.steps_per_period = steps_per_period;
    integrator = std::make_unique<NewmarkIntegrator>(equation, no);
    integrator_settings = {{"alpha", no.alpha}, {"newton_tolerance", no.newton_tolerance}, {"max_newton_iterations", no.max_newton_iterations}};
  } else {
    DormandPrinceOptions dp;
    dp.samples_per_period = steps_per_period;
    integrator = std::make_unique<DormandPrinceIntegrator>(equation, dp);
    integrator_settings = {{"relative_tolerance", dp.relative_tolerance}, {"absolute_tolerance", dp.absolute_tolerance}};
  }
  summary["options"]["simulation"] = simulation_options_json(method, start.has_value(), steps_per_period, steady);
  summary["options"]["simulation"].update(integrator_settings);
  SteadyStateResult r;
  ProgressCallback callback(progress);
  {
    GilRelease release;
    r = integrate_to_steady_state(*integrator, initial, c.outputs, steady, [&](int period, double) {
      return callback(static_cast<double>(period + 1) / steady.max_periods, period, (period + 1) * equation.period());
    });
  }
  callback.rethrow();
  const Table signals{signals_header(c), signals_rows(r)};
  summary["omega"] = omega;
  add_simulation_summary(summary, c, r);
  summary["outputs"] = outputs_json(c);
  py::dict out;
  out["signals"] = signals.columns();
  out["summary"] = to_python(summary);
  callback.mark(out);
  return out;
}

}  // namespace

void bind_timeint(py::module_& m) {
  m.def("simulate", &simulate, py::arg("case"), py::arg("omega"), py::arg("start"), py::arg("method"), py::arg("steps_per_period"),
        py::arg("steady"), py::arg("progress") = py::none(), "time integration to the periodic steady state: {signals, summary}");
}

}  // namespace hbtrack::python
