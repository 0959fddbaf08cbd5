// The blade benchmark (examples/blade/nominal.toml, 567 condensed unknowns, 819 in Hill's
// full system): costs measured in one run, as ratios, because the machine is shared and noisy.
//   - NFRC, with chord iterations (the default) and with plain Newton: wall time, time per
//     corrector iteration against one dense LU of the same size (the library's LU backend and
//     Eigen's), and where the time goes (util/phase_timer.hpp);
//   - stability: Hill's method per point, and its total against the continuation's (target <= 1);
//   - limit-point tracking in the amplitude: cost per accepted point, bordered and extended,
//     against the cost per accepted NFRC point (target for bordered: <= 2).
//
//   build/bench/bench_blade [--quick]     --quick: omega in [2000, 2150] and short tracking legs
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/stability/floquet.hpp"
#include "hbtrack/stability/hill.hpp"
#include "bench_support.hpp"

namespace {

using hbtrack::bench::Breakdown;
using hbtrack::bench::Clock;
using hbtrack::bench::dense_lu_seconds;
using hbtrack::bench::median;
using hbtrack::bench::seconds_since;

// One row: a continuation run and the LU of the size of the system it factors.
struct Run {
  std::string name;
  int unknowns = 0, points = 0, iterations = 0, chord = 0, factorizations = 0;
  double wall = 0;
  Breakdown breakdown;
  void add(const hbtrack::ContinuationSummary& s) {
    iterations += s.newton_iterations;
    chord += s.chord_iterations;
    factorizations += s.factorizations;
  }
};

void print_row(const Run& r, double per_nfrc_point) {
  const int lu_size = r.unknowns + 1;  // the continuation borders the system with its arc-length row
  const double lu = dense_lu_seconds(lu_size), eigen_lu = dense_lu_seconds(lu_size, true);
  const double per_iteration = r.wall / std::max(1, r.iterations);
  const double per_point = r.wall / std::max(1, r.points);
  std::printf("| %s | %d | %d | %d (%d) | %d | %.2f | %.2f | %.2f / %.2f | %.2f | %.2f | %s | %.2f |\n", r.name.c_str(), r.unknowns,
              r.points, r.iterations, r.chord, r.factorizations, r.wall, 1e3 * per_iteration, 1e3 * lu, 1e3 * eigen_lu, per_iteration / lu,
              per_iteration / eigen_lu, r.breakdown.cells().c_str(), per_nfrc_point > 0 ? per_point / per_nfrc_point : 1.0);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hbtrack;
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::vector<std::string> sets{"stability.method=none"};
  if (quick) sets.insert(sets.end(), {"continuation.omega_start=2000", "continuation.omega_end=2150"});
  const CaseDefinition c = load_case(std::string(HBTRACK_SOURCE_DIR) + "/examples/blade/nominal.toml", sets);
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  PhaseTimes::enable(true);

  // NFRC without stability: plain Newton, then chord iterations (the default).
  std::vector<Run> nfrc_runs;
  NfrcResult nfrc;
  for (const bool reuse : {false, true}) {
    NfrcOptions options = c.nfrc;
    options.continuation.reuse_factorization = reuse;
    PhaseTimes::reset();
    const auto t_nfrc = Clock::now();
    nfrc = compute_nfrc(hbm, options, {});
    Run run;
    run.name = reuse ? "NFRC" : "NFRC, plain Newton";
    run.unknowns = hbm.unknowns();
    run.points = nfrc.continuation.summary.points;
    run.wall = seconds_since(t_nfrc);
    run.add(nfrc.continuation.summary);
    run.breakdown = Breakdown::of(run.wall);
    nfrc_runs.push_back(run);
  }
  const double per_point = nfrc_runs.back().wall / nfrc_runs.back().points;

  // Hill on every 8th point (auto: shift-invert Arnoldi at this size).
  std::vector<double> hill_times;
  int unstable = 0;
  for (size_t i = 0; i < nfrc.continuation.points.size(); i += 8) {
    const auto t0 = Clock::now();
    const FloquetResult f = hill_floquet(hbm, nfrc.continuation.points[i].u, nfrc.continuation.points[i].lambda);
    hill_times.push_back(seconds_since(t0));
    unstable += !f.stable;
  }
  const double hill_point = median(hill_times);

  // Tracking of the resonance limit point in the amplitude, both systems.
  const SpecialPoint* lp = nullptr;
  for (const SpecialPoint& sp : nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point && sp.located && (!lp || sp.lambda > lp->lambda)) lp = &sp;
  std::vector<Run> tracking;
  if (lp) {
    const double reference = automatic_length_scale(hbm, c.nfrc.omega_start, c.nfrc.omega_end);
    const FoldScales scales{0.01 * reference, std::abs(c.nfrc.omega_end - c.nfrc.omega_start), force_scale(hbm, reference), 79.0};
    for (TrackingMethod method : {TrackingMethod::bordered, TrackingMethod::extended}) {
      FoldTrackingOptions o;
      o.method = method;
      o.parameter_min = 1.0;
      o.parameter_max = 80.0;
      o.continuation = c.nfrc.continuation;
      o.continuation.max_points = quick ? 10 : 40;
      PhaseTimes::reset();
      const auto t0 = Clock::now();
      const FoldTrackingResult r = track_fold(hbm, hbm.amplitude_parameter(), lp->u, lp->lambda, scales, o, {});
      Run run;
      run.name = to_string(method) + " LP tracking";
      run.unknowns = o.method == TrackingMethod::bordered ? hbm.unknowns() + 1 : 2 * hbm.unknowns() + 1;
      run.points = static_cast<int>(r.points.size());
      run.wall = seconds_since(t0);
      for (const auto& leg : r.legs) run.add(leg);
      run.breakdown = Breakdown::of(run.wall);
      tracking.push_back(run);
    }
  }

  std::printf("Dense LU: %s\n\n", DenseLU::backend().c_str());
  std::printf(
      "| run | unknowns | points | iterations (chord) | LUs | wall [s] | per it. [ms] | dense LU [ms] (backend / Eigen) | "
      "per it. / LU | per it. / Eigen LU | AFT | Jacobian | factorization | rest | per point / NFRC per point |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Run& r : nfrc_runs) print_row(r, per_point);
  for (const Run& r : tracking) print_row(r, per_point);
  std::printf(
      "\nIterations: the corrector's, Newton and chord (in parentheses: chord iterations, a residual and a solve with "
      "kept factors each). LUs: the continuation's dense factorizations (the bordered fold system also factors "
      "its own bordered matrix at each Newton iteration; its chord residuals refine from those factors).\n");
  std::printf(
      "\nStability (Hill's method, %zu points sampled, %d unstable): %.0f ms per point, %.2f x the continuation's cost per point.\n",
      hill_times.size(), unstable, 1e3 * hill_point, hill_point / per_point);
  return 0;
}
