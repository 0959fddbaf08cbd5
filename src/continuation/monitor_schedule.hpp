#pragma once
// Where a costly monitor (BranchMonitor::may_skip_points: Hill's method at every point costs as
// much as the continuation) must be evaluated: near a predicted change of its test functions'
// signs or of the engine's fold test, and at a bounded interval. Private to src/continuation.
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"
#include "special_point_locator.hpp"

namespace hbtrack::continuation_detail {

// An accepted point as the monitor saw it (or has yet to see it): the point, its scaled
// coordinates and tangent in the unknown scale `su` of its time, its test values (the monitor's
// after the engine's two once evaluated) and its arc-length position along the branch.
struct MonitoredPoint {
  BranchPoint point;
  Eigen::VectorXd x, t, su;
  TestValues values;
  double arc = 0;
  int index = 0;
  int verdict = 0;
  bool evaluated() const { return point.monitored; }
};

// The monitor's test functions at the last two evaluated points (values from position 2 on).
struct MonitorHistory {
  std::vector<double> last, before;
  double last_arc = 0, before_arc = 0;
  int points_since = 0;   // accepted since the last evaluated point
  double turn_since = 0;  // how far the tangent turned (radians, summed over the steps) since then
};

// The monitor's verdict changes where the branch bends: near a resonance's peak and its folds,
// where the contact opens and closes. At least one evaluation per this much turn of the tangent
// (the step controller's target_angle per step: every step of a bending stretch is evaluated,
// only the straight stretches away from resonance are not).
inline constexpr double kTurnPerEvaluation = 0.1;

// Whether the monitor must evaluate the point accepted at arc-length position `arc`, whose
// engine test values are `engine_now` and were `engine_before` one step (`step` long) back:
// - no two evaluations to extrapolate from yet, kMaxSkippedPoints skipped already, or the
//   tangent turned by kTurnPerEvaluation since the last evaluation (with this step's `turn`);
// - a test function, linear through its last two evaluations, heading for zero and the point
//   past half the way there (the extrapolation is trusted only half way);
// - the engine's fold or branch-point test changed sign on the step, or the fold test,
//   extrapolated over the step, reaches zero within the next one (a real multiplier crosses
//   +1 there: the points on both sides are evaluated so the verdict's change sits between them).
bool monitor_due(const MonitorHistory& history, double arc, const std::vector<double>& engine_before, const std::vector<double>& engine_now,
                 double step, double turn);

}  // namespace hbtrack::continuation_detail
