#include "hbtrack/runs/simulate.hpp"

#include <memory>
#include <stdexcept>
#include <vector>

#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"

namespace hbtrack::runs {

using nlohmann::json;

namespace {

// The integrator and the settings the summary records of it.
std::unique_ptr<TimeIntegrator> make_integrator(EquationOfMotion& equation, const SimulateOptions& o, json& settings) {
  if (o.method == IntegrationMethod::newmark) {
    NewmarkOptions no;
    no.steps_per_period = o.steps_per_period;
    no.element_steps = o.element_steps;
    settings = {{"alpha", no.alpha},
                {"newton_tolerance", no.newton_tolerance},
                {"max_newton_iterations", no.max_newton_iterations},
                {"element_steps", no.element_steps > 0 ? no.element_steps : no.steps_per_period}};
    return std::make_unique<NewmarkIntegrator>(equation, no);
  }
  DormandPrinceOptions dp;
  dp.samples_per_period = o.steps_per_period;
  settings = {{"relative_tolerance", dp.relative_tolerance}, {"absolute_tolerance", dp.absolute_tolerance}};
  return std::make_unique<DormandPrinceIntegrator>(equation, dp);
}

}  // namespace

RunReport simulate(const CaseDefinition& c, const SimulateOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  SteadyStateOptions steady = o.steady;
  steady.harmonics = c.harmonic_balance.harmonics;
  steady.validate();
  if (o.steps_per_period < 2 * steady.harmonics + 1)
    throw CaseError(o.steps_name + ": must be >= 2*harmonics+1 = " + std::to_string(2 * steady.harmonics + 1) +
                    " to resolve H = " + std::to_string(steady.harmonics) + ", got " + std::to_string(o.steps_per_period));
  HarmonicBalance hbm = make_system(c);
  const int n = c.model.dofs();
  MotionState initial = rest_state(n);
  json summary = {{"verb", "simulate"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  double omega = o.omega.value_or(0.0);
  Eigen::VectorXd orbit;  // harmonics of every dof of the start orbit
  if (o.start) {
    o.start->require_unknowns(hbm.unknowns());
    if (!(o.start->omega > 0) || !std::isfinite(o.start->omega)) throw CaseError(o.start->source + ": omega must be > 0");
    if (!o.omega) omega = o.start->omega;
    orbit = hbm.expand(o.start->x, o.start->omega);
    initial = state_from_harmonics(orbit, n, steady.harmonics, hbm.fundamental(o.start->omega));  // harmonics of omega / nu
    json start = {{"omega", o.start->omega}};
    add_outputs(start, c, record_point(hbm, o.start->x, o.start->omega, c.outputs));
    for (const OutputDof& out : c.outputs) {
      const Eigen::VectorXd h = dof_harmonics(orbit, n, steady.harmonics, out.dof);
      start["harmonics_" + out.name] = std::vector<double>(h.data(), h.data() + h.size());
    }
    summary["start"] = start;
  }
  if (!(omega > 0) || !std::isfinite(omega)) throw CaseError("omega: must be > 0 and finite (or give a start point)");
  std::optional<EquationOfMotion> equation;
  try {
    equation.emplace(c.model, c.elements, hbm.parameters(), omega);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
  // Friction sliders start where the HBM orbit's periodic steady state has them at t = 0.
  if (orbit.size() > 0 && equation->history_size() > 0)
    initial.history = equation->periodic_history(period_samples(orbit, n, steady.harmonics, hbm.basis().samples()));
  json integrator_settings;
  const std::unique_ptr<TimeIntegrator> integrator = make_integrator(*equation, o, integrator_settings);
  summary["omega"] = omega;
  json& simulation = summary["options"]["simulation"] = simulation_options_json(o.method, o.start.has_value(), o.steps_per_period, steady);
  simulation.update(integrator_settings);
  simulation.update(o.origin);
  sink.open();
  sink.summary(summary);

  const auto t_integration = RunClock::now();
  const SteadyStateResult r = integrate_to_steady_state(*integrator, initial, c.outputs, steady, [&](int period, double change) {
    return monitor.period(period, change, (period + 1) * equation->period(), static_cast<double>(period + 1) / steady.max_periods);
  });
  const double integration_s = seconds_since(t_integration);
  const auto signals = sink.table("signals", signals_header(c));
  for (const std::vector<double>& row : signals_rows(r)) signals->append(row);
  add_simulation_summary(summary, c, r);
  summary["stop_reason"] = to_string(monitor.stop_reason(r.stop_reason));
  summary["outputs"] = outputs_json(c);
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"integration_s", integration_s}};
  sink.summary(summary);

  RunReport report{summary};
  if (!r.converged) {
    const std::string why = r.stop_reason == StopReason::max_periods
                                ? "no periodic steady state within " + std::to_string(r.periods) + " periods (last change " +
                                      std::to_string(r.last_change) + ")"
                                : to_string(r.stop_reason) + (r.message.empty() ? "" : ": " + r.message);
    report.failure = "simulate stopped: " + why + " (kept in " + sink.location() + ")";
  } else {
    char brief[200];
    std::snprintf(brief, sizeof brief, "periodic after %d periods (%s, %ld steps)", r.periods, to_string(o.method).c_str(),
                  r.statistics.steps);
    report.brief = brief;
    if (!c.outputs.empty() && !r.outputs.empty())
      report.brief += ", h1_" + c.outputs[0].name + " " + std::to_string(r.outputs[0].first_harmonic());
  }
  return report;
}

}  // namespace hbtrack::runs
