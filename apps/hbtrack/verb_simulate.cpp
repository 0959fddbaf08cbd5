// `hbtrack simulate`: time integration of the full model to its periodic steady state, from rest
// or from a point of a harmonic balance result (`--from DIR --point K`), to check HBM solutions
// and whether the motion stays on them (docs/time-integration.md).
#include <cstdio>
#include <optional>
#include <sstream>

#include "cli_common.hpp"
#include "hbtrack/runs/fold_search.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "hbtrack/runs/simulate.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

using nlohmann::json;

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
  std::string omega, from, point, near_lp;
  std::string distances = "0.2,0.5,1,2,3,5";  // percent of omega from the LP
  std::string method = "newmark";
  std::string steps_per_period = "256";
  std::string element_steps = "0";
  std::string max_periods = "2000";
  std::string record_periods = "1";
};

// --distances: increasing percentages of omega, each > 0.
std::vector<double> parse_distances(const std::string& text) {
  std::vector<double> fractions;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    const double percent = parse_positive("--distances", item);
    if (!fractions.empty() && percent / 100 <= fractions.back()) throw CaseError("--distances: must increase, got " + text);
    fractions.push_back(percent / 100);
  }
  if (fractions.empty()) throw CaseError("--distances: give at least one percentage, got an empty list");
  return fractions;
}

// --near-lp K: integrations from rows of the NFRC's stable side of LP K, closest first, until
// one holds the orbit (hbtrack/runs/fold_search.hpp).
runs::RunReport simulate_near_fold(const SimulateOptions& o, long k, const std::vector<double>& distances, const CaseDefinition& c,
                                   const runs::SimulateOptions& run, ResultFolderSink& sink, runs::RunMonitor& monitor) {
  const json points = read_summary(o.from).value("special_points", json::array());
  const json& lp = points[runs::special_point_index(points, SpecialPointType::limit_point, k, {"--near-lp", o.from + "/summary.json"})];
  const CsvTable branch = read_csv_table(o.from + "/branch.csv");
  if (std::find(branch.header.begin(), branch.header.end(), "stable") == branch.header.end())
    throw CaseError(branch.path + ": no column stable: --near-lp needs an NFRC computed with stability on");
  const auto stable = static_cast<size_t>(branch.column("stable"));
  const auto amplitude = c.outputs.empty() ? 0 : static_cast<size_t>(branch.column("h1_" + c.outputs[0].name));
  std::vector<runs::FoldSearchRow> rows;
  for (const auto& r : branch.rows) rows.push_back({r[0], r[stable] == 1.0, c.outputs.empty() ? 0.0 : r[amplitude]});
  runs::FoldSearchOptions search;
  search.simulate = run;
  search.lp = static_cast<int>(k);
  search.lp_omega = lp.value("omega", 0.0);
  search.candidates = runs::fold_search_rows(rows, lp.value("index", 0L), search.lp_omega, distances, branch.path);
  const HarmonicBalance hbm = make_system(c);
  search.start_at = [&](long row) {
    const HbmState s = read_hbm_state(o.from + "/states.csv", row, hbm);
    return runs::StartPoint{s.omega, s.x, o.from + "/states.csv: point " + std::to_string(row)};
  };
  search.origin = {{"from", o.from}, {"near_lp", k}};
  return runs::simulate_near_fold(c, search, sink, monitor);
}

int run_simulate(const SimulateOptions& o) {
  const auto t0 = Clock::now();
  // Flags first: they are cheap to check and their errors name them.
  const IntegrationMethod method = parse_flag_choice<IntegrationMethod>("--method", o.method);
  const int steps_per_period = static_cast<int>(parse_integer("--steps-per-period", o.steps_per_period, 1));
  const int element_steps = static_cast<int>(parse_integer("--element-steps", o.element_steps, 0));
  if (element_steps > 0 && method != IntegrationMethod::newmark) throw CaseError("--element-steps: only with --method newmark");
  SteadyStateOptions steady;
  steady.max_periods = static_cast<int>(parse_integer("--max-periods", o.max_periods, 1));
  steady.record_periods = static_cast<int>(parse_integer("--record-periods", o.record_periods, 1));
  if (steady.record_periods > steady.max_periods) throw CaseError("--record-periods: must be <= --max-periods");
  std::optional<double> omega_flag;
  if (!o.omega.empty()) omega_flag = parse_positive("--omega", o.omega);
  if (!o.near_lp.empty() && (o.from.empty() || !o.point.empty() || !o.omega.empty()))
    throw CaseError("--near-lp: needs --from, and neither --point nor --omega (it chooses its own points)");
  if (o.near_lp.empty() && o.from.empty() != o.point.empty())
    throw CaseError(o.from.empty() ? "--point: needs --from" : "--from: needs --point or --near-lp");
  const long near_lp = o.near_lp.empty() ? 0 : parse_integer("--near-lp", o.near_lp, 1);
  const std::vector<double> distances = parse_distances(o.distances);
  const long point = o.point.empty() ? -1 : parse_integer("--point", o.point, 0);
  if (o.from.empty() && !omega_flag) throw CaseError("--omega: required unless --from gives the point");

  CaseDefinition c = load_case(o.common.case_path, o.common.sets);
  runs::SimulateOptions run;
  run.omega = omega_flag;
  run.method = method;
  run.steps_per_period = steps_per_period;
  run.element_steps = element_steps;
  run.steady = steady;
  if (!o.from.empty()) {
    std::vector<std::string> overrides = hbm_overrides(o.from, c);
    overrides.insert(overrides.end(), o.common.sets.begin(), o.common.sets.end());  // --set wins
    c = load_case(o.common.case_path, overrides);
  }
  if (!o.point.empty()) {
    const HbmState s = read_hbm_state(o.from + "/states.csv", point, make_system(c));
    run.start = runs::StartPoint{s.omega, s.x, o.from + "/states.csv: point " + o.point};
    run.origin = {{"from", o.from}, {"point", point}};
  }
  ResultFolderSink sink(o.common.out_dir);
  PeriodLine monitor(progress_style(o.common.quiet));
  const runs::RunReport report =
      o.near_lp.empty() ? runs::simulate(c, run, sink, monitor) : simulate_near_fold(o, near_lp, distances, c, run, sink, monitor);
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
  simulate
      ->add_option("--near-lp", options.near_lp,
                   "with --from: integrate from the NFRC's stable side of its limit point K, closest first, until the orbit holds")
      ->type_name("K");
  simulate->add_option("--distances", options.distances, "with --near-lp: the starts' distances from the LP, in percent of omega")
      ->type_name("LIST")
      ->capture_default_str();
  simulate->add_option("--method", options.method, "newmark (implicit HHT-alpha) or dopri5 (adaptive explicit Dormand-Prince)")
      ->type_name("NAME")
      ->capture_default_str();
  simulate
      ->add_option("--steps-per-period", options.steps_per_period,
                   "newmark: base time steps per period; dopri5: output samples per period (the step adapts)")
      ->type_name("INT")
      ->capture_default_str();
  simulate
      ->add_option("--element-steps", options.element_steps,
                   "newmark: steps per period of the elements' fastest rate where a step is halved (0: --steps-per-period)")
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
