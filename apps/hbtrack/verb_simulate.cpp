// `hbtrack simulate`: time integration of the full model to its periodic steady state, from rest
// or from a point of a harmonic balance result (`--from DIR --point K`), to check HBM solutions
// and whether the motion stays on them (docs/time-integration.md).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "cli_common.hpp"
#include "folder_lock.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;


// Numeric flags arrive as text and are checked here, so that a bad value gives the tool's
// one-line CaseError (exit 2) naming the flag.
struct SimulateOptions {
  CommonOptions common;
  std::string omega, from, point;
  std::string method = "newmark";
  std::string steps_per_period = "256";
  std::string max_periods = "2000";
  std::string record_periods = "1";
};

int run_simulate(const SimulateOptions& o) {
  const auto t0 = Clock::now();
  // Flags first: they are cheap to check and their errors name them.
  const IntegrationMethod method = parse_flag_choice<IntegrationMethod>("--method", o.method);
  const int steps_per_period = static_cast<int>(parse_integer("--steps-per-period", o.steps_per_period, 1));
  SteadyStateOptions steady;
  steady.max_periods = static_cast<int>(parse_integer("--max-periods", o.max_periods, 1));
  steady.record_periods = static_cast<int>(parse_integer("--record-periods", o.record_periods, 1));
  if (steady.record_periods > steady.max_periods) throw CaseError("--record-periods: must be <= --max-periods");
  std::optional<double> omega_flag;
  if (!o.omega.empty()) omega_flag = parse_positive("--omega", o.omega);
  if (o.from.empty() != o.point.empty()) throw CaseError(o.from.empty() ? "--point: needs --from" : "--from: needs --point");
  const long point = o.point.empty() ? -1 : parse_integer("--point", o.point, 0);
  if (o.from.empty() && !omega_flag) throw CaseError("--omega: required unless --from gives the point");

  CaseDefinition c = load_case(o.common.case_path, o.common.sets);
  if (!o.from.empty()) {
    std::vector<std::string> overrides = hbm_overrides(o.from, c);
    overrides.insert(overrides.end(), o.common.sets.begin(), o.common.sets.end());  // --set wins
    c = load_case(o.common.case_path, overrides);
  }
  HarmonicBalance hbm = make_system(c);
  const int harmonics = c.harmonic_balance.harmonics;
  if (steps_per_period < 2 * harmonics + 1)
    throw CaseError("--steps-per-period: must be >= 2*harmonics+1 = " + std::to_string(2 * harmonics + 1) + " to resolve H = " +
                    std::to_string(harmonics) + ", got " + o.steps_per_period);
  steady.harmonics = harmonics;

  // The initial state: rest, or the HBM orbit at t = 0 (at the frequency of that orbit).
  const int n = c.model.dofs();
  MotionState initial = rest_state(n);
  std::optional<RecordedPoint> start_point;
  std::vector<Eigen::VectorXd> start_harmonics;  // of each output dof: the HBM orbit to compare with
  double omega = omega_flag.value_or(0.0);
  Eigen::VectorXd orbit;  // harmonics of every dof of the start orbit
  if (!o.from.empty()) {
    const HbmState s = read_hbm_state(o.from + "/states.csv", point, hbm);
    if (s.x.size() != hbm.unknowns())
      throw CaseError(o.from + "/states.csv: holds " + std::to_string(s.x.size()) + " unknowns, the case's harmonic balance has " +
                      std::to_string(hbm.unknowns()) + " (results of another case?)");
    if (!(s.omega > 0) || !std::isfinite(s.omega)) throw CaseError(o.from + "/states.csv: point " + o.point + ": omega must be > 0");
    if (!omega_flag) omega = s.omega;
    const Eigen::VectorXd full = hbm.expand(s.x, s.omega);
    orbit = full;
    initial = state_from_harmonics(full, n, harmonics, hbm.fundamental(s.omega));  // harmonics of omega / nu
    for (const OutputDof& out : c.outputs) start_harmonics.push_back(dof_harmonics(full, n, harmonics, out.dof));
    start_point = record_point(hbm, s.x, s.omega, c.outputs);
  }

  std::optional<EquationOfMotion> equation;
  try {
    equation.emplace(c.model, c.elements, hbm.parameters(), omega);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
  // Friction sliders start where the HBM orbit's periodic steady state has them at t = 0.
  if (orbit.size() > 0 && equation->history_size() > 0)
    initial.history = equation->periodic_history(period_samples(orbit, n, harmonics, hbm.basis().samples()));
  std::unique_ptr<TimeIntegrator> integrator;
  json method_options;
  if (method == IntegrationMethod::newmark) {
    NewmarkOptions no;
    no.steps_per_period = steps_per_period;
    integrator = std::make_unique<NewmarkIntegrator>(*equation, no);
    method_options = {{"alpha", no.alpha}, {"newton_tolerance", no.newton_tolerance}, {"max_newton_iterations", no.max_newton_iterations}};
  } else {
    DormandPrinceOptions dp;
    dp.samples_per_period = steps_per_period;
    integrator = std::make_unique<DormandPrinceIntegrator>(*equation, dp);
    method_options = {{"relative_tolerance", dp.relative_tolerance}, {"absolute_tolerance", dp.absolute_tolerance}};
  }

  ensure_directory(o.common.out_dir);
  lock_result_folder(o.common.out_dir);
  json summary = {
      {"verb", "simulate"}, {"options", options_json(c, hbm)}, {"omega", omega}, {"stop_reason", to_string(StopReason::running)}};
  summary["options"]["simulation"] = simulation_options_json(method, !o.from.empty(), steps_per_period, steady);
  summary["options"]["simulation"].update(method_options);
  if (!o.from.empty()) {
    summary["options"]["simulation"]["from"] = o.from;
    summary["options"]["simulation"]["point"] = point;
    json start = {{"omega", start_point->omega}};
    add_outputs(start, c, *start_point);
    for (size_t i = 0; i < c.outputs.size(); ++i) {
      std::string key = "harmonics_";
      key += c.outputs[i].name;
      start[key] = std::vector<double>(start_harmonics[i].data(), start_harmonics[i].data() + start_harmonics[i].size());
    }
    summary["start"] = start;
  }
  write_json_atomically(o.common.out_dir + "/summary.json", summary);

  const bool show_progress = !o.common.quiet && isatty(STDERR_FILENO);
  const auto t_integration = Clock::now();
  const SteadyStateResult r = integrate_to_steady_state(*integrator, initial, c.outputs, steady, [&](int period, double change) {
    if (show_progress) std::fprintf(stderr, "\r  period %6d  change %-10.3e", period + 1, change);
    return !interrupted();
  });
  const double integration_s = seconds_since(t_integration);
  if (show_progress) std::fprintf(stderr, "\n");

  CsvAppender signals(o.common.out_dir + "/signals.csv", signals_header(c));
  for (const std::vector<double>& row : signals_rows(r)) signals.append(row);
  add_simulation_summary(summary, c, r);
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"integration_s", integration_s}};
  write_json_atomically(o.common.out_dir + "/summary.json", summary);

  if (!r.converged) {
    const std::string why = r.stop_reason == StopReason::max_periods
                                ? "no periodic steady state within " + std::to_string(r.periods) + " periods (last change " +
                                      std::to_string(r.last_change) + ")"
                                : to_string(r.stop_reason) + (r.message.empty() ? "" : ": " + r.message);
    throw RunFailed{"simulate stopped: " + why + " (kept in " + o.common.out_dir + ")"};
  }
  if (!o.common.quiet) {
    std::fprintf(stderr, "simulate: periodic after %d periods (%s, %ld steps), %.3f s", r.periods, o.method.c_str(),
                 r.statistics.steps, summary["timings"]["wall_s"].get<double>());
    if (!c.outputs.empty() && !r.outputs.empty())
      std::fprintf(stderr, ", h1_%s %.6g", c.outputs[0].name.c_str(), r.outputs[0].first_harmonic());
    std::fprintf(stderr, " -> %s\n", o.common.out_dir.c_str());
  }
  return 0;
}

void add_simulate_verbs(CLI::App& app, VerbList& verbs) {
  static SimulateOptions options;
  CLI::App* simulate = app.add_subcommand("simulate", "time integration to the periodic steady state (checks HBM solutions)");
  add_common_options(simulate, options.common);
  simulate->add_option("--omega", options.omega, "forcing frequency (rad/s); default with --from: that point's")->type_name("FLOAT");
  simulate->add_option("--from", options.from, "frc or solve result folder: start on one of its points")->type_name("DIR");
  simulate->add_option("--point", options.point, "row of DIR/branch.csv to start from (0-based), with --from")->type_name("INT");
  simulate->add_option("--method", options.method, "newmark (implicit HHT-alpha) or dopri5 (adaptive explicit Dormand-Prince)")
      ->type_name("NAME")
      ->capture_default_str();
  simulate->add_option("--steps-per-period", options.steps_per_period,
                       "newmark: base time steps per period; dopri5: output samples per period (the step adapts)")
      ->type_name("INT")
      ->capture_default_str();
  simulate->add_option("--max-periods", options.max_periods, "period budget")->type_name("INT")->capture_default_str();
  simulate->add_option("--record-periods", options.record_periods, "last periods written to signals.csv")
      ->type_name("INT")
      ->capture_default_str();
  verbs.push_back({simulate, [] { return run_simulate(options); }});
}

const VerbRegistrar registrar(add_simulate_verbs);

}  // namespace

}  // namespace hbtrack::cli
