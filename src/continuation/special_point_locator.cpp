#include "special_point_locator.hpp"

#include <algorithm>
#include <cmath>

namespace hbtrack::continuation_detail {

bool Locator::point_at(const VectorXd& x0, const VectorXd& t0, double arc, VectorXd& y, Tangent& tan) {
  y = x0 + arc * t0;
  int iterations = 0;
  if (!s.correct(y, x0, t0, arc, false, options, iterations)) return false;
  tan = s.tangent(t0);
  return true;
}

double Locator::value(size_t which, const VectorXd& y, const Tangent& tan, double reference_log_det) {
  if (which == 0) return tan.t(s.m);
  if (which == 1) return tan.det_sign * std::exp(std::min(tan.log_det - reference_log_det, 600.0));
  BranchPoint p{s.unknowns(y), s.parameter(y), tan.t, 0, 0};
  return monitor->test_functions(p)[which - 2];
}

bool Locator::locate(size_t which, const VectorXd& x0, const VectorXd& t0, double f0, const VectorXd& x1, double f1,
                     double reference_log_det, VectorXd& y_out, Tangent& tan_out) {
  double a = 0, fa = f0, b = t0.dot(x1 - x0), fb = f1;
  const double span = b;
  int side = 0;
  // The test function's own values at the bracket's ends (Illinois scales the stale one), to
  // tell a jump (a C0 law's multiplier leaping across the circle) from a zero: a function that
  // is continuous there is small at both ends once the bracket is small.
  double value_a = std::abs(f0), value_b = std::abs(f1);
  const double smallest_end = std::min(value_a, value_b);
  const auto jumps = [&](double width, double fraction) {
    return std::abs(b - a) <= width * span && std::min(value_a, value_b) > fraction * smallest_end;
  };
  for (int it = 0; it < 60; ++it) {
    double c = b - fb * (b - a) / (fb - fa);
    // Near the zero the test function is roundoff, and the secant may leave the bracket:
    // bisect instead.
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    // On a jump Illinois gains a decade in about four steps, bisection in 3.3.
    if (jumps(1e-3, 0.1)) c = 0.5 * (a + b);
    VectorXd y;
    Tangent tan;
    if (!point_at(x0, t0, c, y, tan)) return false;
    if ((y - (x0 + (c / span) * (x1 - x0))).norm() > (x1 - x0).norm()) return false;
    const double fc = value(which, y, tan, reference_log_det);
    y_out = y;
    tan_out = tan;
    if (fc == 0.0 || std::abs(b - a) <= 1e-12 * span) return true;
    if ((fc > 0) == (fb > 0)) {
      value_b = std::abs(fc);
      b = c, fb = fc;
      if (side == -1) fa *= 0.5;  // Illinois: halve the stale end so it cannot stall
      side = -1;
    } else {
      value_a = std::abs(fc);
      a = c, fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
    if (std::abs(b - a) <= 1e-12 * span) return true;
    // A monitor's jump is located to 1e-6 of the step (4e-9 in omega on NLvib's two-dof
    // example, far below its truncation error of 1e-6), a zero to 1e-12: the 20 more halvings
    // cost 20 Floquet evaluations (shooting, on that example) and changed none of its reported
    // digits. The engine's own tests cost a corrector each, and a fold at a corner of a
    // piecewise-linear branch is a jump of the LP test located to the corrector's tolerance.
    if (which >= 2 && jumps(1e-6, 1e-3)) return true;
  }
  return false;
}

}  // namespace hbtrack::continuation_detail
