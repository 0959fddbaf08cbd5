// The blade benchmark (examples/blade/nominal.toml, 567 condensed unknowns, 819 in Hill's
// full system): costs measured in one run, as ratios, because the machine is shared and noisy.
//   - NFRC: wall time, cost per Jacobian evaluation against one dense LU of the same size;
//   - stability: Hill's method per point, and its total against the continuation's (target <= 1);
//   - limit-point tracking in the amplitude: cost per accepted point, bordered and extended,
//     against the cost per accepted NFRC point (target for bordered: <= 2).
//
//   build/bench/bench_blade [--quick]     --quick: omega in [2000, 2150] and short tracking legs
#include <Eigen/LU>
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

using hbtrack::bench::Clock;
using hbtrack::bench::dense_lu_seconds;
using hbtrack::bench::median;
using hbtrack::bench::seconds_since;

}  // namespace

int main(int argc, char** argv) {
  using namespace hbtrack;
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  std::vector<std::string> sets{"stability.method=none"};
  if (quick) sets.insert(sets.end(), {"continuation.omega_start=2000", "continuation.omega_end=2150"});
  const CaseDefinition c = load_case(std::string(HBTRACK_SOURCE_DIR) + "/examples/blade/nominal.toml", sets);
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);

  // NFRC without stability.
  const auto t_nfrc = Clock::now();
  const NfrcResult nfrc = compute_nfrc(hbm, c.nfrc, {});
  const double nfrc_s = seconds_since(t_nfrc);
  const auto& s = nfrc.continuation.summary;
  const double lu_s = dense_lu_seconds(hbm.unknowns() + 1);
  const double per_jacobian = nfrc_s / s.jacobian_evaluations;
  const double per_point = nfrc_s / s.points;

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
    if (sp.type == "LP" && sp.located && (!lp || sp.lambda > lp->lambda)) lp = &sp;
  double tracking[2] = {0, 0};
  int tracking_points[2] = {0, 0}, tracking_iterations[2] = {0, 0};
  if (lp) {
    const double reference = automatic_length_scale(hbm, c.nfrc.omega_start, c.nfrc.omega_end);
    const FoldScales scales{0.01 * reference, std::abs(c.nfrc.omega_end - c.nfrc.omega_start), force_scale(hbm, reference), 79.0};
    for (int m = 0; m < 2; ++m) {
      FoldTrackingOptions o;
      o.method = m == 0 ? "bordered" : "extended";
      o.parameter_min = 1.0;
      o.parameter_max = 80.0;
      o.continuation = c.nfrc.continuation;
      o.continuation.max_points = quick ? 10 : 40;
      const auto t0 = Clock::now();
      const FoldTrackingResult r = track_fold(hbm, hbm.amplitude_parameter(), lp->u, lp->lambda, scales, o, {});
      tracking[m] = seconds_since(t0);
      tracking_points[m] = static_cast<int>(r.points.size());
      for (const auto& leg : r.legs) tracking_iterations[m] += leg.newton_iterations;
    }
  }

  std::printf("| unknowns | points | Jacobians | NFRC [s] | per Jacobian / dense LU | Hill per point [ms] | stability / continuation | "
              "bordered tracking per point / NFRC per point | extended / NFRC per point | unstable sampled |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %d | %d | %d | %.1f | %.2f | %.0f | %.2f | %.2f (%d points, %d Newton it.) | %.2f (%d points, %d Newton it.) | %d of %zu |\n",
              hbm.unknowns(), s.points, s.jacobian_evaluations, nfrc_s, per_jacobian / lu_s, 1e3 * hill_point,
              hill_point * s.points / nfrc_s, tracking_points[0] ? tracking[0] / tracking_points[0] / per_point : 0.0, tracking_points[0],
              tracking_iterations[0], tracking_points[1] ? tracking[1] / tracking_points[1] / per_point : 0.0, tracking_points[1],
              tracking_iterations[1], unstable, hill_times.size());
  return 0;
}
