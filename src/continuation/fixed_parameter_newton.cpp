#include "fixed_parameter_newton.hpp"

#include "hbtrack/util/dense_lu.hpp"
#include "hbtrack/util/phase_timer.hpp"
#include "scaled_problem.hpp"  // inf_norm

namespace hbtrack::continuation_detail {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

int plain_newton(ContinuationProblem& problem, VectorXd& u, double lambda, double tolerance, int max_iterations, int& used) {
  VectorXd r, r_lambda;
  MatrixXd jac;
  DenseLU lu;
  const double scale = problem.residual_scale();
  used = 0;
  for (int it = 0; it <= max_iterations; ++it) {
    problem.evaluate(u, lambda, r, &jac, &r_lambda);
    if (!r.allFinite()) return -1;
    if (inf_norm(r) <= tolerance * scale) return it;
    if (it == max_iterations) break;
    const ScopedPhase timing(Phase::factorization);
    lu.compute(jac);
    r = -r;
    lu.solve_in_place(r);
    ++used;
    if (!r.allFinite()) return -1;
    u += r;
  }
  return -1;
}

// Halvings of the step before giving up: 2^-20 of a Newton step no longer moves a piecewise
// affine residual off the kink it is stuck on.
constexpr int kHalvings = 20;

}  // namespace

int damped_newton(ContinuationProblem& problem, VectorXd& u, double lambda, double tolerance, int max_iterations, int& used) {
  VectorXd r, r_lambda, trial, r_trial;
  MatrixXd jac;
  DenseLU lu;
  const double scale = problem.residual_scale();
  used = 0;
  problem.evaluate(u, lambda, r, &jac, &r_lambda);
  for (int it = 0; it <= max_iterations; ++it) {
    if (!r.allFinite()) return -1;
    if (inf_norm(r) <= tolerance * scale) return it;
    if (it == max_iterations) break;
    VectorXd step = -r;
    {
      const ScopedPhase timing(Phase::factorization);
      lu.compute(jac);
      lu.solve_in_place(step);
    }
    ++used;
    if (!step.allFinite()) return -1;
    const double merit = r.squaredNorm();
    double alpha = 1.0;
    bool decreased = false;
    for (int halving = 0; halving <= kHalvings && !decreased; ++halving, alpha *= 0.5) {
      trial = u + alpha * step;
      problem.evaluate(trial, lambda, r_trial, nullptr, nullptr);
      decreased = r_trial.allFinite() && r_trial.squaredNorm() <= (1.0 - 1e-4 * alpha) * merit;
    }
    if (!decreased) return -1;
    u = trial;
    problem.evaluate(u, lambda, r, &jac, &r_lambda);
  }
  return -1;
}

int fixed_parameter_newton(ContinuationProblem& problem, VectorXd& u, double lambda, double tolerance, int max_iterations, int& used) {
  const VectorXd start = u;
  const int iterations = plain_newton(problem, u, lambda, tolerance, max_iterations, used);
  if (iterations >= 0 || !problem.has_corners()) return iterations;
  int damped_used = 0;
  u = start;
  const int damped = damped_newton(problem, u, lambda, tolerance, max_iterations, damped_used);
  used += damped_used;
  return damped >= 0 ? used : -1;
}

}  // namespace hbtrack::continuation_detail

namespace hbtrack {

int newton_at_fixed_parameter(ContinuationProblem& problem, Eigen::VectorXd& u, double lambda, double tolerance, int max_iterations) {
  int used = 0;
  return continuation_detail::fixed_parameter_newton(problem, u, lambda, tolerance, max_iterations, used);
}

}  // namespace hbtrack
