#include "step_control.hpp"

#include <algorithm>
#include <cmath>

namespace hbtrack::continuation_detail {

namespace {

// A corrector that converged without a step (the prediction was on the branch) or in fewer
// iterations than the target can take a longer step; the prediction's error grows as the
// step squared, so the ratio of iterations is a conservative guide (as before this controller).
double corrector_factor(double work, int target_iterations) { return work <= 0 ? kMaxStepFactor : target_iterations / work; }

// A smooth branch turns in proportion to the step (turn ~ curvature x step): the step that
// turns by target_angle. Points then sit as densely as the curvature needs, where the cap
// used to space them evenly.
double curvature_factor(double turn, double target_angle) { return turn > 0 ? target_angle / turn : kMaxStepFactor; }

// A test function heading for zero: extrapolated linearly, it crosses at distance d ahead. A
// step of about 2d brackets the crossing in a short interval (a second special point close
// behind it is not stepped over, and the locator's secant starts close), and is never
// shorter than needed to reach it, so steps do not shrink onto the zero.
double special_point_factor(const AcceptedStep& s) {
  double factor = kMaxStepFactor;
  const size_t n = std::min(s.before.size(), s.after.size());
  for (size_t k = 0; k < n; ++k) {
    const double f0 = std::abs(s.before[k]), f1 = std::abs(s.after[k]);
    if (!(s.before[k] * s.after[k] > 0) || !(f1 < f0)) continue;  // crossed, or moving away
    const double distance = s.step * f1 / (f0 - f1);
    factor = std::min(factor, 2 * distance / s.step);
  }
  return factor;
}

}  // namespace

double step_factor(const AcceptedStep& s, const ContinuationOptions& options) {
  // The corrector's and the special points' factors shrink at most 2-fold, as the iteration
  // ratio did before: a hard corrector or a near zero are no reason to collapse the step.
  const double factor = std::min({std::max(corrector_factor(s.work, options.target_iterations), 0.5),
                                  curvature_factor(s.turn, options.target_angle), std::max(special_point_factor(s), 0.5)});
  return std::clamp(factor, kMinStepFactor, kMaxStepFactor);
}

}  // namespace hbtrack::continuation_detail
