// `hbtrack frc`: the NFRC by arc-length continuation; `hbtrack solve`: one periodic solution.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "hbtrack/io/results_writer.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;


int run_frc(const CommonOptions& o) {
  const auto t0 = Clock::now();
  const CaseDefinition c = load_case(o.case_path, o.sets);
  HarmonicBalance hbm = make_system(c);
  ensure_directory(o.out_dir);
  CsvAppender branch(o.out_dir + "/branch.csv", branch_header(c));
  CsvAppender states(o.out_dir + "/states.csv", state_header(hbm.unknowns()));
  json summary = {{"verb", "frc"}, {"options", options_json(c, hbm)}, {"stop_reason", "running"}};
  write_json_atomically(o.out_dir + "/summary.json", summary);

  Progress progress(o.quiet);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs, [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    branch.append(branch_row(rec));
    states.append(state_row(p.lambda, p.u));
    progress.update(index, p.lambda, rec, c.outputs);
    return !interrupted();
  });
  add_nfrc_summary(summary, c, hbm, r);
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", r.continuation.summary.wall_s}};
  // The state of each special point, in summary order: `track` starts from a limit point's.
  CsvAppender special_states(o.out_dir + "/special_states.csv", state_header(hbm.unknowns()));
  for (const auto& sp : r.continuation.special_points) special_states.append(state_row(sp.lambda, sp.u));
  write_json_atomically(o.out_dir + "/summary.json", summary);
  const auto& s = r.continuation.summary;
  if (!r.continuation.success())
    throw RunFailed{"continuation stopped: " + s.stop_reason + " after " + std::to_string(s.points) + " points (kept in " + o.out_dir + ")"};
  if (!o.quiet)
    std::fprintf(stderr, "frc: %d points, %d special points, %d Newton iterations, %.3f s -> %s\n", s.points,
                 static_cast<int>(r.continuation.special_points.size()), s.newton_iterations, summary["timings"]["wall_s"].get<double>(), o.out_dir.c_str());
  return 0;
}

int run_solve(const CommonOptions& o, double omega) {
  const auto t0 = Clock::now();
  const CaseDefinition c = load_case(o.case_path, o.sets);
  if (!(omega > 0) || !std::isfinite(omega)) throw CaseError("--omega: must be > 0 and finite");
  HarmonicBalance hbm = make_system(c);
  ensure_directory(o.out_dir);
  const auto& co = c.nfrc.continuation;
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, co.tolerance, 4 * co.max_iterations);
  json summary = {{"verb", "solve"},
                  {"options", options_json(c, hbm)},
                  {"omega", omega},
                  {"converged", s.converged},
                  {"stop_reason", s.converged ? "converged" : "no_convergence"},
                  {"points", s.converged ? 1 : 0},
                  {"newton_iterations", std::max(s.newton_iterations, 0)},
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
    CsvAppender states(o.out_dir + "/states.csv", state_header(hbm.unknowns()));
    states.append(state_row(omega, s.x));
    add_outputs(summary, c, s.recorded);
  }
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  write_json_atomically(o.out_dir + "/summary.json", summary);
  if (!s.converged) throw RunFailed{"Newton did not converge at omega = " + std::to_string(omega)};
  if (!o.quiet) std::fprintf(stderr, "solve: converged in %d Newton iterations -> %s\n", s.newton_iterations, o.out_dir.c_str());
  return 0;
}

void add_frc_verbs(CLI::App& app, VerbList& verbs) {
  static CommonOptions frc_options, solve_options;
  static double omega = 0;
  CLI::App* frc = app.add_subcommand("frc", "nonlinear frequency response curve by arc-length continuation in omega");
  add_common_options(frc, frc_options);
  verbs.push_back({frc, [] { return run_frc(frc_options); }});
  CLI::App* solve = app.add_subcommand("solve", "one periodic solution at a fixed frequency");
  add_common_options(solve, solve_options);
  solve->add_option("--omega", omega, "forcing frequency (rad/s)")->required();
  verbs.push_back({solve, [] { return run_solve(solve_options, omega); }});
}

const VerbRegistrar registrar(add_frc_verbs);

}  // namespace

}  // namespace hbtrack::cli
