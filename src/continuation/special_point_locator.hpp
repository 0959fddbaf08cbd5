#pragma once
// Special points between two accepted points: the test-function values at a point (the engine's
// LP and BP, then a monitor's) and the zero of one of them located along the branch. Private to
// src/continuation.
#include <vector>

#include "scaled_problem.hpp"

namespace hbtrack::continuation_detail {

// Test-function values at a point: engine's LP and BP first, then the monitor's.
struct TestValues {
  std::vector<double> values;
  double bp_log_det = 0;  // BP is stored relative to this, so values stay in range
};

// Zero of one test function between two accepted points, by the Illinois variant of the secant
// method on the pseudo-arclength coordinate s along the tangent `t0` at the first point; where
// the function jumps across zero instead (a C0 law), by bisection onto the jump.
struct Locator {
  Scaled& s;
  const ContinuationOptions& options;
  BranchMonitor* monitor;

  // Corrected point at plane coordinate `arc` from x0; fills its tangent. False if Newton fails.
  bool point_at(const VectorXd& x0, const VectorXd& t0, double arc, VectorXd& y, Tangent& tan);
  double value(size_t which, const VectorXd& y, const Tangent& tan, double reference_log_det);
  // Returns true and the located point when the iteration converged on the bracket's stretch of
  // branch: a corrected point further than the bracket's length from the chord x0 -> x1 is on
  // another part of the curve (a sharp turn within the step, as an NS curve makes where its
  // frequency reaches 0), and the zero is then left unlocated.
  bool locate(size_t which, const VectorXd& x0, const VectorXd& t0, double f0, const VectorXd& x1, double f1, double reference_log_det,
              VectorXd& y_out, Tangent& tan_out);
};

}  // namespace hbtrack::continuation_detail
