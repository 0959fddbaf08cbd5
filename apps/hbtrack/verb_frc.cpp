// `hbtrack frc`: the NFRC by arc-length continuation; `hbtrack solve`: one periodic solution.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <filesystem>
#include <optional>

#include "artefact_warnings.hpp"
#include "cli_common.hpp"
#include "failure_advice.hpp"
#include "folder_lock.hpp"
#include "hbtrack/results/continuation_state_file.hpp"
#include "hbtrack/results/element_force_table.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "result_folder.hpp"
#include "resume_checkpoint.hpp"
#include "stop_request.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct FrcOptions {
  CommonOptions common;
  std::string resume;     // a stopped frc result folder to continue
  std::string from;       // a result folder whose point starts the NFRC
  std::string point;      // its row in states.csv (0-based; default: the last)
  double time_limit = 0;  // seconds, 0 for none
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
  HbmState start;
  long start_row = -1;
  const CaseDefinition c = options.from.empty() ? load_case(o.case_path, o.sets) : case_from_point(options, start, start_row);
  HarmonicBalance hbm = make_system(c);
  if (!options.from.empty()) start = read_hbm_state(options.from + "/states.csv", start_row, hbm);
  if (!options.from.empty() && start.x.size() != hbm.unknowns())
    throw CaseError(options.from + "/states.csv: holds " + std::to_string(start.x.size()) + " unknowns, the case's harmonic balance has " +
                    std::to_string(hbm.unknowns()) + " (results of another case?)");
  json summary = {{"verb", "frc"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  if (!options.from.empty()) summary["started_from"] = {{"folder", options.from}, {"point", start_row}, {"omega", start.omega}};
  const json settings = branch_settings(summary["options"]);
  std::optional<SavedContinuation> resumed;
  if (!options.resume.empty()) {
    const std::vector<StopReason> finished{StopReason::reached_end, StopReason::left_range, StopReason::closed};
    resumed = checkpoint_to_resume(dir, finished, settings, read_continuation_state);
  }
  ensure_directory(dir);
  lock_result_folder(dir);
  const int rows_kept = resumed ? resumed->state.points : 0;
  // A resumed run appends to its CSVs; a folder that does not fit its checkpoint is bad input.
  CsvAppender branch = open_result_csv(dir + "/branch.csv", branch_header(c), resumed.has_value(), rows_kept);
  CsvAppender states = open_result_csv(dir + "/states.csv", dof_state_header(hbm), resumed.has_value(), rows_kept);
  // stability.csv: several rows per point (its Floquet exponents), so resumed by point index.
  std::optional<CsvAppender> stability;
  if (c.nfrc.stability.enabled()) {
    if (!resumed) {
      stability.emplace(dir + "/stability.csv", stability_header());
    } else {
      try {
        stability.emplace(CsvAppender::continuing_points(dir + "/stability.csv", stability_header(), rows_kept));
      } catch (const std::runtime_error& e) {
        throw CaseError(std::string("--resume: ") + e.what());
      }
    }
  }
  std::optional<CsvAppender> forces;
  if (options.element_forces) forces.emplace(open_result_csv(dir + "/element_forces.csv", element_force_header(hbm), resumed.has_value(), rows_kept));
  int point = rows_kept;
  if (resumed) summary["resumed_at_point"] = rows_kept;
  write_json_atomically(dir + "/summary.json", summary);

  Progress progress(o.quiet, c.nfrc.omega_start, c.nfrc.omega_end);
  progress.relay_to(o.progress_file);
  StopRequest stop(options.time_limit);
  ContinuationRestart restart;
  if (resumed) restart.resume_from = &resumed->state;
  // After every accepted point (and step-size update): what --resume needs to go on from there.
  restart.on_state = [&](const ContinuationState& state) { write_continuation_state(dir + "/checkpoint.json", state, settings); };
  const RecordedObserver record = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    branch.append(branch_row(rec));
    states.append(dof_state_row(hbm, p.lambda, p.u));
    if (forces) forces->append(element_force_row(hbm, p.lambda, p.u));
    if (stability)
      for (const auto& row : stability_rows(point, rec)) stability->append(row);
    ++point;
    progress.update(index, p.lambda, rec, c.outputs);
    return !stop.requested();
  };
  NfrcResult r;
  if (options.from.empty()) {
    r = compute_nfrc(hbm, c.nfrc, c.outputs, record, restart);
  } else {
    const double end = c.nfrc.omega_end;
    const ParameterWindow window{std::min(start.omega, end), std::max(start.omega, end), end > start.omega ? 1 : -1, false};
    r = compute_branch(hbm, c.nfrc, c.outputs, start.x, start.omega, window, record, restart);
  }
  progress.finish();
  const auto& s = r.continuation.summary;
  const std::string stop_reason = to_string(stop.reason(s.stop_reason));
  add_nfrc_summary(summary, c, hbm, r);
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", s.wall_s}, {"stability_s", r.stability_s}};
  // The state of each special point, in summary order: `track` starts from a limit point's.
  CsvAppender special_states(dir + "/special_states.csv", dof_state_header(hbm));
  for (const auto& sp : r.continuation.special_points) special_states.append(dof_state_row(hbm, sp.lambda, sp.u));
  std::vector<std::string> warnings =
      special_point_clusters(r.continuation.special_points, std::abs(c.nfrc.omega_end - c.nfrc.omega_start));
  for (std::string& w : unconfirmed_hill_bifurcations(r.continuation.special_points, first_nonsmooth_element(c), c.harmonic_balance.harmonics))
    warnings.push_back(std::move(w));
  summary["warnings"] = warnings;
  for (const std::string& w : warnings) std::fprintf(stderr, "frc: warning: %s\n", w.c_str());
  const double last_omega = r.recorded.empty() ? c.nfrc.omega_start : r.recorded.back().omega;
  if (!r.continuation.success()) summary["advice"] = continuation_failure_advice(s, c.nfrc.continuation, last_omega);
  write_json_atomically(dir + "/summary.json", summary);
  if (!r.continuation.success()) {
    std::string reason = "continuation stopped: ";
    reason += stop_reason;
    reason += " after " + std::to_string(s.points);
    reason += " points (kept in " + dir + "): " + summary["advice"].get<std::string>();
    throw RunFailed{reason};
  }
  if (!o.quiet)
    std::fprintf(stderr, "frc: %d points, %d special points, %d Newton iterations, %.3f s -> %s\n", s.points,
                 static_cast<int>(r.continuation.special_points.size()), s.newton_iterations, summary["timings"]["wall_s"].get<double>(), dir.c_str());
  return 0;
}

int run_solve(const CommonOptions& o, double omega) {
  const auto t0 = Clock::now();
  const CaseDefinition c = load_case(o.case_path, o.sets);
  if (!(omega > 0) || !std::isfinite(omega)) throw CaseError("--omega: must be > 0 and finite");
  HarmonicBalance hbm = make_system(c);
  ensure_directory(o.out_dir);
  lock_result_folder(o.out_dir);
  const auto& co = c.nfrc.continuation;
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, co.tolerance, 4 * co.max_iterations);
  json summary = {{"verb", "solve"},
                  {"options", options_json(c, hbm)},
                  {"omega", omega},
                  {"converged", s.converged},
                  {"stop_reason", to_string(s.converged ? StopReason::converged : StopReason::no_convergence)},
                  {"points", s.converged ? 1 : 0},
                  // A failed solve spent every iteration it was allowed (the message says so).
                  {"newton_iterations", s.converged ? s.newton_iterations : 4 * co.max_iterations},
                  {"failed_steps", s.converged ? 0 : 1},
                  {"special_points", json::array()}};
  if (s.converged) {
    RecordedPoint rec = s.recorded;
    if (c.nfrc.stability.enabled()) {
      const FloquetResult f = floquet(hbm, s.x, omega, c.nfrc.stability);
      rec.stable = f.stable ? 1 : 0;
      summary["stable"] = f.stable;
      summary["max_floquet_real"] = f.max_real;
      json multipliers = json::array();
      for (Eigen::Index i = 0; i < f.multipliers.size(); ++i) multipliers.push_back({f.multipliers(i).real(), f.multipliers(i).imag()});
      summary["floquet_multipliers"] = multipliers;
    }
    CsvAppender branch(o.out_dir + "/branch.csv", branch_header(c));
    branch.append(branch_row(rec));
    CsvAppender states(o.out_dir + "/states.csv", dof_state_header(hbm));
    states.append(dof_state_row(hbm, omega, s.x));
    add_outputs(summary, c, s.recorded);
  }
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  write_json_atomically(o.out_dir + "/summary.json", summary);
  if (!s.converged)
    throw RunFailed{"Newton did not converge at omega = " + std::to_string(omega) + " in " + std::to_string(4 * co.max_iterations) +
                    " iterations from the linear solution: solve nearer the linear regime, or raise continuation.max_iterations"};
  if (!o.quiet) std::fprintf(stderr, "solve: converged in %d Newton iterations -> %s\n", s.newton_iterations, o.out_dir.c_str());
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

const VerbRegistrar registrar(add_frc_verbs);

}  // namespace

}  // namespace hbtrack::cli
