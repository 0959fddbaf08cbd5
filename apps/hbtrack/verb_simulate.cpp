// `hbtrack simulate`: time integration of the full model to its periodic steady state, from rest
// or from a point of a harmonic balance result (`--from DIR --point K`), to check HBM solutions
// and whether the motion stays on them (docs/time-integration.md).
#include <cstdio>
#include <optional>

#include "cli_common.hpp"
#include "hbtrack/runs/simulate.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

namespace {

// The integration's progress ("period N change X"): rewritten in place on a terminal, a plain
// line at most every progress_line_interval_s() in a log (progress.hpp); and Ctrl-C.
class PeriodLine final : public runs::RunMonitor {
 public:
  explicit PeriodLine(ProgressStyle style) : style_(style) {}
  bool period(int period, double change, double, double) override {
    if (style_ == ProgressStyle::terminal) {
      std::fprintf(stderr, "\r  period %6d  change %-10.3e", period + 1, change);
      shown_ = true;
    } else if (style_ == ProgressStyle::lines && Clock::now() - last_line_ >= std::chrono::duration<double>(progress_line_interval_s())) {
      std::fprintf(stderr, "period %d  change %.3e\n", period + 1, change);
      last_line_ = Clock::now();
    }
    return !interrupted();
  }
  void finish() const {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  ProgressStyle style_;
  bool shown_ = false;
  Clock::time_point last_line_ = Clock::now();
};

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
  runs::SimulateOptions run;
  run.omega = omega_flag;
  run.method = method;
  run.steps_per_period = steps_per_period;
  run.steady = steady;
  if (!o.from.empty()) {
    std::vector<std::string> overrides = hbm_overrides(o.from, c);
    overrides.insert(overrides.end(), o.common.sets.begin(), o.common.sets.end());  // --set wins
    c = load_case(o.common.case_path, overrides);
    const HbmState s = read_hbm_state(o.from + "/states.csv", point, make_system(c));
    run.start = runs::StartPoint{s.omega, s.x, o.from + "/states.csv: point " + o.point};
    run.origin = {{"from", o.from}, {"point", point}};
  }
  ResultFolderSink sink(o.common.out_dir);
  PeriodLine monitor(progress_style(o.common.quiet));
  const runs::RunReport report = runs::simulate(c, run, sink, monitor);
  monitor.finish();
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.common.quiet)
    std::fprintf(stderr, "simulate: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
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
  simulate
      ->add_option("--steps-per-period", options.steps_per_period,
                   "newmark: base time steps per period; dopri5: output samples per period (the step adapts)")
      ->type_name("INT")
      ->capture_default_str();
  simulate->add_option("--max-periods", options.max_periods, "period budget")->type_name("INT")->capture_default_str();
  simulate->add_option("--record-periods", options.record_periods, "last periods written to signals.csv")
      ->type_name("INT")
      ->capture_default_str();
  verbs.push_back({simulate, [] { return run_simulate(options); }});
}

const VerbRegistrar simulate_registrar(add_simulate_verbs);

}  // namespace

}  // namespace hbtrack::cli
