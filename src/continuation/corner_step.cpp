#include "corner_step.hpp"

namespace hbtrack::continuation_detail {

namespace {

// Largest misfit of the straight line R(x + s t) = (s - delta) R_s to the residual at the
// prediction, relative to that residual: within one affine piece the line is exact up to the
// residual's curvature in lambda, O(ds); a second corner in reach bends it by O(1).
constexpr double kLineFit = 1e-2;
// A corner closer to x than this fraction of the step is x itself: the step is refused (and
// halved by the caller), rather than a point put on top of x.
constexpr double kNearestCorner = 1e-3;

}  // namespace

bool step_to_corner(Scaled& s, const VectorXd& x, const VectorXd& t, int det_sign, double ds, const ContinuationOptions& options,
                    VectorXd& corner, Tangent& outgoing, int& iterations) {
  const VectorXd predicted = x + ds * t;
  s.evaluate(predicted);
  if (!s.r.allFinite() || !s.jac.allFinite()) return false;
  const VectorXd r_beyond = s.r;
  // dR/ds along t in the next piece: the scaled Jacobian times t.
  const VectorXd slope = s.jac * s.su.cwiseProduct(t.head(s.m)) + s.r_lambda * (s.sl * t(s.m));
  const double slope_norm = slope.squaredNorm();
  if (!(slope_norm > 0)) return false;
  Tangent beyond = s.tangent(t);  // the next piece's tangent, oriented along t for now
  const double delta = ds - slope.dot(r_beyond) / slope_norm;
  const double misfit = (r_beyond + (delta - ds) * slope).norm() / r_beyond.norm();
  if (!(delta > kNearestCorner * ds && delta < ds) || !(misfit <= kLineFit)) return false;
  corner = x + delta * t;
  int used = 0;
  const bool converged = s.correct(corner, x, t, delta, false, options, used);
  iterations += used;
  if (!converged) return false;
  if (beyond.det_sign != det_sign) {
    beyond.t = -beyond.t;
    beyond.det_sign = -beyond.det_sign;
  }
  outgoing = beyond;
  return true;
}

}  // namespace hbtrack::continuation_detail
