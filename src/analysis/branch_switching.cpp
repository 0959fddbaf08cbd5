#include "hbtrack/analysis/branch_switching.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

SwitchedBranch switch_at_branch_point(HarmonicBalance& hbm, const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                                      const VectorXd& x_bp, double omega_bp, const VectorXd& known, bool both_ways, bool local_steps,
                                      const RecordedObserver& leg_observer) {
  options.validate();
  const int n = hbm.unknowns();
  if (x_bp.size() != n || known.size() != n + 1) throw std::invalid_argument("switch: state sizes do not match the system");
  // The NFRC's units (compute_branch), so that the step means what it means along the NFRC.
  const bool adaptive = options.length_scale == 0;
  const double reference = adaptive ? automatic_length_scale(hbm, options.omega_start, options.omega_end) : options.length_scale;
  NfrcProblem problem(hbm, adaptive ? 0.01 * reference : reference, std::abs(options.omega_end - options.omega_start),
                      force_scale(hbm, reference), adaptive);
  const VectorXd s = problem.unknown_scale(x_bp);
  const double sl = problem.parameter_scale(), rs = problem.residual_scale();

  // Scaled extended Jacobian at the BP and its two smallest right singular vectors.
  VectorXd r, r_omega;
  MatrixXd jac;
  problem.evaluate(x_bp, omega_bp, r, &jac, &r_omega);
  MatrixXd extended(n, n + 1);
  extended.leftCols(n) = jac * s.asDiagonal() / rs;
  extended.col(n) = r_omega * sl / rs;
  const Eigen::JacobiSVD<MatrixXd> svd(extended, Eigen::ComputeFullV);
  const MatrixXd null_space = svd.matrixV().rightCols(2);
  VectorXd k(n + 1);
  k.head(n) = known.head(n).cwiseQuotient(s);
  k(n) = known(n) / sl;
  if (!(k.norm() > 0)) throw std::invalid_argument("switch: the known branch's direction is zero");
  const Eigen::Vector2d c = null_space.transpose() * k.normalized();
  SwitchedBranch out;
  out.tangent = null_space * Eigen::Vector2d(-c(1), c(0));
  out.tangent.normalize();

  // Predictor a few steps along it; corrector on the hyperplane normal to it (scaled Newton).
  VectorXd y0(n + 1);
  y0.head(n) = x_bp.cwiseQuotient(s);
  y0(n) = omega_bp / sl;
  VectorXd target, y;
  MatrixXd bordered(n + 1, n + 1);
  VectorXd f(n + 1);
  bool converged = false;
  double distance = 2 * options.continuation.step;
  for (double h = distance; !converged && h >= options.continuation.step / 32; h /= 2) {
    distance = h;
    target = y0 + h * out.tangent;
    y = target;
    for (int it = 0; it < 4 * options.continuation.max_iterations && !converged; ++it) {
      const VectorXd x = y.head(n).cwiseProduct(s);
      problem.evaluate(x, y(n) * sl, r, &jac, &r_omega);
      f.head(n) = r / rs;
      f(n) = out.tangent.dot(y - target);
      if (!f.allFinite()) break;
      converged = f.head(n).cwiseAbs().maxCoeff() <= options.continuation.tolerance && std::abs(f(n)) <= 1e-12;
      if (converged) break;
      bordered.topLeftCorner(n, n) = jac * s.asDiagonal() / rs;
      bordered.topRightCorner(n, 1) = r_omega * sl / rs;
      bordered.row(n) = out.tangent.transpose();
      y -= bordered.partialPivLu().solve(f);
    }
  }
  if (!converged) throw std::runtime_error("switch: Newton did not converge on the new branch next to the branch point");
  out.x1 = y.head(n).cwiseProduct(s);
  out.omega1 = y(n) * sl;

  // Both ways from the new point: the engine leaves in the direction of omega's change, so
  // the way that increases the distance to the BP follows the tangent's omega component;
  // when that is zero (a pitchfork in omega) either way is tried.
  const double lo = std::min(options.omega_start, options.omega_end), hi = std::max(options.omega_start, options.omega_end);
  const int away = out.omega1 >= omega_bp ? 1 : -1;
  NfrcOptions legs = options;
  if (local_steps) {
    legs.continuation.step_max = std::max(distance, legs.continuation.step_min);
    legs.continuation.step = std::max(distance / 2, legs.continuation.step_min);
  }
  out.away = compute_branch(hbm, legs, outputs, out.x1, out.omega1, ParameterWindow{lo, hi, away, true}, leg_observer);
  if (both_ways) out.through = compute_branch(hbm, legs, outputs, out.x1, out.omega1, ParameterWindow{lo, hi, -away, true}, leg_observer);
  return out;
}

}  // namespace hbtrack
