// `hbtrack frc`: the NFRC by arc-length continuation; `hbtrack solve`: one periodic solution.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <filesystem>
#include <optional>

#include "cli_common.hpp"
#include "cli_monitor.hpp"
#include "hbtrack/runs/frc.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"
#include "resume_command.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct FrcOptions {
  CommonOptions common;
  std::string resume;           // a stopped frc result folder to continue
  std::string from;             // a result folder whose point starts the NFRC
  std::string point;            // its row in states.csv (0-based; default: the last)
  double time_limit = 0;        // seconds, 0 for none
  bool element_forces = false;  // element_forces.csv: every element's force per point
};

// The case as the NFRC from a point of another result sees it: that result's parameters and
// harmonic balance (--set still wins), and the frequency range from the point's omega to the
// case's omega_end. Fills `start` with the point and `row` with its row.
CaseDefinition case_from_point(const FrcOptions& options, HbmState& start, long& row) {
  const CommonOptions& o = options.common;
  const std::string states = options.from + "/states.csv";
  const long rows = static_cast<long>(read_csv_table(states).rows.size());
  row = options.point.empty() ? rows - 1 : parse_integer("--point", options.point, 0);
  start.omega = read_state_omega(states, row);  // the unknowns once the case's system is built
  if (!(start.omega > 0) || !std::isfinite(start.omega))
    throw CaseError(states + ": point " + std::to_string(row) + ": omega must be > 0 and finite");
  char omega[64];
  std::snprintf(omega, sizeof omega, "continuation.omega_start=%.17g", start.omega);
  std::vector<std::string> sets = o.sets;
  sets.emplace_back(omega);  // the NFRC starts at the point
  std::optional<CaseDefinition> plain;
  try {
    plain.emplace(load_case(o.case_path, sets));
  } catch (const CaseError& e) {
    // The case's own check of the range, said in terms of --from.
    if (std::string(e.what()).find("omega_end: must differ from omega_start") == std::string::npos) throw;
    throw CaseError("--from: point " + std::to_string(row) + " of " + states + " is at omega_end = " + std::to_string(start.omega) +
                    ": give the new end with --set continuation.omega_end=VALUE");
  }
  // The source's parameters and harmonic balance, then --set and the start.
  std::vector<std::string> overrides = hbm_overrides(options.from, *plain);
  overrides.insert(overrides.end(), sets.begin(), sets.end());
  return load_case(o.case_path, overrides);
}

int run_frc(const FrcOptions& options) {
  const CommonOptions& o = options.common;
  const auto t0 = Clock::now();
  if (o.out_dir.empty() && options.resume.empty()) throw CaseError("--output is required (or --resume DIR)");
  if (!o.out_dir.empty() && !options.resume.empty() && o.out_dir != options.resume)
    throw CaseError("--resume: continues in its own folder, give no other -o");
  if (options.from.empty() && !options.point.empty()) throw CaseError("--point: needs --from");
  const std::string dir = options.resume.empty() ? o.out_dir : options.resume;
  runs::FrcOptions run;
  run.element_forces = options.element_forces;
  HbmState start;
  long start_row = -1;
  const CaseDefinition c = options.from.empty() ? load_case(o.case_path, o.sets) : case_from_point(options, start, start_row);
  if (!options.from.empty()) {
    // The unknowns are recovered from the point's harmonics by the case's own system.
    start = read_hbm_state(options.from + "/states.csv", start_row, runs::make_system_at(c, c.harmonic_balance.harmonics));
    run.start = runs::StartPoint{start.omega, start.x, options.from + "/states.csv"};
    run.started_from = {{"folder", options.from}, {"point", start_row}, {"omega", start.omega}};
  }
  ResultFolderSink sink(dir, !options.resume.empty());
  Progress progress(o.quiet, run.start ? start.omega : c.nfrc.omega_start, c.nfrc.omega_end);
  progress.relay_to(o.progress_file);
  StopRequest stop(options.time_limit);
  CliMonitor monitor(progress, stop, c.outputs);
  const runs::RunReport report = runs::frc(c, run, sink, monitor);
  progress.finish();
  for (const auto& w : report.summary["warnings"]) std::fprintf(stderr, "frc: warning: %s\n", w.get<std::string>().c_str());
  if (!report.success()) throw RunFailed{report.failure, resume_advice(report.summary.value("stop_reason", ""), resume_command(dir))};
  if (!o.quiet) std::fprintf(stderr, "frc: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), dir.c_str());
  return 0;
}

int run_solve(const CommonOptions& o, double omega) {
  const CaseDefinition c = load_case(o.case_path, o.sets);
  ResultFolderSink sink(o.out_dir);
  const runs::RunReport report = runs::solve(c, omega, sink);
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.quiet) std::fprintf(stderr, "solve: %s -> %s\n", report.brief.c_str(), o.out_dir.c_str());
  return 0;
}

void add_frc_verbs(CLI::App& app, VerbList& verbs) {
  static FrcOptions frc_options;
  static CommonOptions solve_options;
  static double omega = 0;
  CLI::App* frc = app.add_subcommand("frc", "nonlinear frequency response curve by arc-length continuation in omega");
  add_common_options(frc, frc_options.common);
  frc->get_option("--output")->required(false);  // --resume DIR names the folder instead
  frc->add_option("--resume", frc_options.resume, "continue the stopped frc run in this folder (same case and --set)");
  frc->add_option("--from", frc_options.from,
                  "start from a point of this frc/solve/continue result (its parameters and harmonic balance), towards omega_end")
      ->type_name("DIR");
  frc->add_option("--point", frc_options.point, "row of DIR/states.csv to start from (0-based; default the last)")->type_name("INT");
  frc->add_flag("--element-forces", frc_options.element_forces,
                "also write element_forces.csv: each nonlinear element's force harmonics, max and min per point");
  add_time_limit_option(frc, frc_options.time_limit);
  verbs.push_back({frc, [] { return run_frc(frc_options); }});
  CLI::App* solve = app.add_subcommand("solve", "one periodic solution at a fixed frequency");
  add_common_options(solve, solve_options);
  solve->add_option("--omega", omega, "forcing frequency (rad/s)")->required();
  verbs.push_back({solve, [] { return run_solve(solve_options, omega); }});
}

const VerbRegistrar frc_registrar(add_frc_verbs);

}  // namespace

}  // namespace hbtrack::cli
