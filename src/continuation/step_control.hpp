#pragma once
// The length of the next continuation step, from how the last accepted one went: sized by
// accuracy (how far the tangent turned, how hard the corrector worked, how fast the
// special-point test functions head for zero), with step_max only as a safety bound. Private
// to src/continuation.
#include <vector>

#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack::continuation_detail {

// What the controller reads of the step just accepted.
struct AcceptedStep {
  double step = 0;  // its arc-length step (scaled)
  double work = 0;  // corrector iterations, a chord iteration counting half
  double turn = 0;  // angle between the tangents at its two ends (radians)
  // Test functions at its two ends, only those whose zero is worth approaching with short
  // steps (the bordered determinant is not: its magnitude is no distance to a branch point).
  std::vector<double> before, after;
};

// Factor on the step for the next one: the smallest of the corrector's (target_iterations /
// work), the curvature's (target_angle / turn) and the special points' (a step about twice
// the distance to the nearest zero predicted by linear extrapolation), within
// [kMinStepFactor, kMaxStepFactor].
double step_factor(const AcceptedStep& s, const ContinuationOptions& options);

// Growth per step at most 2: a straight, easy stretch reaches step_max from the initial step in
// a few points. Shrinking at most 4-fold: a step that turned more than max_angle (twice the
// default target_angle) was rejected and halved instead.
inline constexpr double kMaxStepFactor = 2.0;
inline constexpr double kMinStepFactor = 0.25;

}  // namespace hbtrack::continuation_detail
