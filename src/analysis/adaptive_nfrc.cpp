#include "hbtrack/analysis/adaptive_nfrc.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace hbtrack {

namespace {

// Points passed on after a change of H was put off before the criterion is asked again: the
// change waits until the branch has left the fold or stability change that put it off.
constexpr int kPointsBeforeRetry = 3;

// A scaled tangent (lambda last) on the unknowns of `to` harmonics. NfrcProblem's unit is the
// same for every unknown and follows max|u|, which the added zeros do not change: padding maps it.
Eigen::VectorXd tangent_with_harmonic_count(const Eigen::VectorXd& t, int dofs, int to) {
  const Eigen::Index m = t.size() - 1;
  Eigen::VectorXd out(static_cast<Eigen::Index>(dofs) * (2 * to + 1) + 1);
  out.head(out.size() - 1) = with_harmonic_count(t.head(m), dofs, to);
  out(out.size() - 1) = t(m);
  return out;
}

BranchPoint padded_point(const BranchPoint& p, int dofs, int to) {
  BranchPoint out = p;
  out.u = with_harmonic_count(p.u, dofs, to);
  if (p.tangent.size() > 0) out.tangent = tangent_with_harmonic_count(p.tangent, dofs, to);
  return out;
}

RecordedPoint padded_record(RecordedPoint rec, int harmonics, int to) {
  rec.balanced_harmonics = harmonics;
  for (OutputValues& o : rec.outputs) o.harmonics = with_harmonic_count(o.harmonics, 1, to);
  rec.harmonic_numbers.clear();
  for (int k = 0; k <= to; ++k) rec.harmonic_numbers.push_back(k);
  return rec;
}

void add_counts(ContinuationSummary& total, const ContinuationSummary& s) {
  total.newton_iterations += s.newton_iterations;
  total.failed_steps += s.failed_steps;
  total.step_halvings += s.step_halvings;
  total.jacobian_evaluations += s.jacobian_evaluations;
  total.factorizations += s.factorizations;
  total.chord_iterations += s.chord_iterations;
  total.residual_evaluations += s.residual_evaluations;
  total.corners_stepped_over += s.corners_stepped_over;
}

// What the two sides of a junction must agree on: the engine's fold test (the sign of the
// tangent's omega component) and the stability verdict. A fold or a stability change that the
// new H moves across the junction would otherwise be lost, or found a second time.
struct JunctionSide {
  int fold_sign = 0;
  int stable = -1;
};
JunctionSide side_of(const BranchPoint& p, const RecordedPoint& rec) { return {p.tangent(p.tangent.size() - 1) >= 0 ? 1 : -1, rec.stable}; }

// A point of the branch and the H it was balanced with (unpadded).
struct SegmentEnd {
  int harmonics = 0;
  BranchPoint point;
  JunctionSide side;
};

// Whether the special point lies past `from` on the step to `to` (the sign of its offset along
// the chord, in the units of the arc length: max|u| and the omega range).
bool ahead_of(const BranchPoint& from, const BranchPoint& to, const SpecialPoint& sp, double omega_range) {
  const double unit = std::max(from.u.cwiseAbs().maxCoeff(), 1e-300);
  return (sp.u - from.u).dot(to.u - from.u) / (unit * unit) +
             (sp.lambda - from.lambda) * (to.lambda - from.lambda) / (omega_range * omega_range) >
         0;
}

struct Resolved {
  int harmonics = 0;
  Eigen::VectorXd x;
};

// The point p (balanced with h harmonics) solved again at its omega with `wanted` harmonics
// and, with `climb` while they are more than h, with one more as long as the top share stays
// above add_above (the last that converged). nullopt when Newton fails at `wanted`.
std::optional<Resolved> solve_with_harmonics(const SystemWithHarmonics& system_with, const AdaptiveHarmonics& a, const BranchPoint& p,
                                             int dofs, int h, int wanted, bool climb, const ContinuationOptions& co,
                                             int& newton_iterations) {
  std::optional<Resolved> solved;
  for (int trial = wanted;; ++trial) {
    const Eigen::VectorXd guess = with_harmonic_count(solved ? solved->x : p.u, dofs, trial);
    const FixedFrequencySolution s = solve_at_frequency(system_with(trial), p.lambda, {}, co.tolerance, 3 * co.max_iterations, &guess);
    newton_iterations += std::max(s.newton_iterations, 0);
    if (!s.converged) break;
    solved = Resolved{trial, s.x};
    if (!climb || trial < h || trial >= a.max || top_harmonic_share(s.x, dofs, trial) <= a.add_above) break;
  }
  return solved;
}

}  // namespace

NfrcResult compute_adaptive_nfrc(const SystemWithHarmonics& system_with, const AdaptiveHarmonics& adaptive, const AdaptiveStart& start,
                                 const NfrcOptions& options, const std::vector<OutputDof>& outputs, const RecordedObserver& observer) {
  adaptive.validate();
  const auto clock_start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count(); };
  const int top = adaptive.max;
  // The NFRC's own window when it starts from omega_start.
  const ParameterWindow window = start.x.size() > 0 ? start.window
                                                    : ParameterWindow{std::min(options.omega_start, options.omega_end),
                                                                      std::max(options.omega_start, options.omega_end),
                                                                      options.omega_end >= options.omega_start ? 1 : -1, false};
  NfrcResult total;
  ContinuationSummary& counts = total.continuation.summary;
  StopReason stop = StopReason::running;

  // The next segment: from x0 at omega0 with h harmonics (x0 empty: the NFRC's own start),
  // leaving along `along` when set.
  int h = start.harmonics;
  Eigen::VectorXd x0 = start.x;
  double omega0 = start.omega;
  std::optional<Eigen::VectorXd> along;
  bool first_passed_on = false;            // x0 is the last point passed on (a change put off goes on from it)
  std::optional<JunctionSide> other_side;  // x0 is a junction: its old side
  SegmentEnd before_junction;              // where a change put off goes on from
  int quiet_until = 0;                     // no change asked before this many points
  double step = options.continuation.step;
  int passed = 0;

  while (true) {
    if (passed >= options.continuation.max_points) {
      stop = StopReason::max_points;
      break;
    }
    NfrcOptions segment = options;
    segment.continuation.step = std::clamp(step, options.continuation.step_min, options.continuation.step_max);
    segment.continuation.max_points = options.continuation.max_points - passed + (first_passed_on ? 1 : 0);
    if (options.continuation.wall_time_limit > 0) {
      segment.continuation.wall_time_limit = options.continuation.wall_time_limit - elapsed();
      if (segment.continuation.wall_time_limit <= 0) {
        stop = StopReason::time_limit;
        break;
      }
    }
    HarmonicBalance& hbm = system_with(h);
    const int q = hbm.retained_dofs();
    const int offset = passed - (first_passed_on ? 1 : 0);  // the branch index of this segment's point 0
    std::optional<int> wanted;
    bool sides_differ = false, stopped_by_caller = false;
    SegmentEnd last;  // the last point of the segment kept
    int last_index = -1;
    std::optional<SegmentEnd> too_few;  // the point after it, which asked for more harmonics
    const RecordedObserver segment_observer = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
      if (index == 0 && other_side) {
        const JunctionSide side = side_of(p, rec);
        if (side.fold_sign != other_side->fold_sign || side.stable != other_side->stable) {
          sides_differ = true;
          return false;
        }
      }
      // Not at a junction (its H was chosen there), nor where a lazy stability monitor passed the
      // point on before the one it evaluated (the points after it are settled already).
      const bool ask = !(index == 0 && along) && passed >= quiet_until && p.monitored;
      const int next = ask ? next_harmonic_count(adaptive, p.u, q, h) : h;
      if (next > h && last_index >= 0) {
        // Too few harmonics for the step that reached p (a limit point in it was located with
        // them): p is dropped and the step done again with more, from the point before it.
        too_few = SegmentEnd{h, p, side_of(p, rec)};
        wanted = next;
        return false;
      }
      last = {h, p, side_of(p, rec)};
      last_index = index;
      if (index > 0 || !first_passed_on) {
        total.continuation.points.push_back(padded_point(p, q, top));
        total.recorded.push_back(padded_record(rec, h, top));
        const int branch_index = passed++;
        if (observer && !observer(total.continuation.points.back(), total.recorded.back(), branch_index)) {
          stopped_by_caller = true;
          return false;
        }
      }
      if (next != h) wanted = next;
      return !wanted;
    };
    ContinuationRestart restart;
    if (along) restart.leave_along = &*along;
    const NfrcResult r = x0.size() == 0 ? compute_nfrc(hbm, segment, outputs, segment_observer)
                                        : compute_branch(hbm, segment, outputs, x0, omega0, window, segment_observer, restart);
    add_counts(counts, r.continuation.summary);
    total.stability_s += r.stability_s;
    total.length_scale = r.length_scale;
    const double omega_range = std::abs(options.omega_end - options.omega_start);
    for (SpecialPoint sp : r.continuation.special_points) {
      // Beyond the junction: the next segment finds it.
      if (wanted && (sp.index > last_index || (too_few && sp.index == last_index && ahead_of(last.point, too_few->point, sp, omega_range))))
        continue;
      sp.index += offset;
      sp.u = with_harmonic_count(sp.u, q, top);
      if (sp.tangent.size() > 0) sp.tangent = tangent_with_harmonic_count(sp.tangent, q, top);
      total.continuation.special_points.push_back(std::move(sp));
    }
    if (stopped_by_caller) {
      stop = StopReason::interrupted;
      break;
    }
    // A change put off: on at the old H from the point that asked for it, as if it had not stopped.
    const auto put_off_from = [&](const SegmentEnd& end) {
      h = end.harmonics;
      x0 = end.point.u;
      omega0 = end.point.lambda;
      along = end.point.tangent;
      first_passed_on = true;
      other_side.reset();
      quiet_until = passed + kPointsBeforeRetry;
    };
    if (sides_differ) {
      put_off_from(before_junction);
      continue;
    }
    if (!wanted) {
      stop = r.continuation.summary.stop_reason;
      break;
    }
    // The junction, at the last point kept: solved again at its omega with the harmonics that the
    // point after it needs (found there: one more while its top share stays above add_above), or
    // with those it asks for itself.
    const ContinuationOptions& co = options.continuation;
    int target = *wanted;
    if (too_few)
      if (const auto needed =
              solve_with_harmonics(system_with, adaptive, too_few->point, q, h, *wanted, true, co, counts.newton_iterations))
        target = needed->harmonics;
    const auto junction = solve_with_harmonics(system_with, adaptive, last.point, q, h, target, !too_few, co, counts.newton_iterations);
    before_junction = last;
    if (!junction) {  // Newton failed at the new H (on a fold, say)
      put_off_from(last);
      continue;
    }
    h = junction->harmonics;
    x0 = junction->x;
    omega0 = last.point.lambda;
    along = tangent_with_harmonic_count(last.point.tangent, q, h);
    first_passed_on = false;
    other_side = last.side;
    const double last_step = too_few ? too_few->point.step : last.point.step;
    if (last_step > 0) step = last_step;
  }
  counts.points = passed;
  counts.stop_reason = stop;
  counts.wall_s = elapsed();
  return total;
}

}  // namespace hbtrack
