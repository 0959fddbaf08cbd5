#pragma once
// Newton on R(u, lambda) = 0 at a fixed lambda (the first point of a branch, a landing on the end
// of the range, newton_at_fixed_parameter). Private to src/continuation.
#include <Eigen/Dense>

#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack::continuation_detail {

// Plain Newton from u; when it fails on a problem with corners (ContinuationProblem::has_corners,
// a residual only piecewise smooth in u), Newton again from the same u with a backtracking line
// search on ||R||^2 (damped_newton). Returns the iterations spent (of both runs), -1 when neither
// converged; `used` counts the iterations spent, also when it fails.
int fixed_parameter_newton(ContinuationProblem& problem, Eigen::VectorXd& u, double lambda, double tolerance, int max_iterations,
                           int& used);

// Newton whose step is shortened until the residual decreases enough: the step d = -J^-1 R with
// length alpha = 1, 1/2, 1/4, ... down to kMinimumDamping, the first with
// ||R(u + alpha d)||^2 <= (1 - 1e-4 alpha) ||R(u)||^2 (Armijo's rule). On a piecewise affine
// residual (a sampled stick-slip or contact law) plain Newton may cycle between the patterns of
// two pieces, each step landing on the affine solution of the other piece; a step that must
// lower ||R|| cannot cycle. Returns the iterations (-1: no decrease possible, or not converged).
int damped_newton(ContinuationProblem& problem, Eigen::VectorXd& u, double lambda, double tolerance, int max_iterations, int& used);

}  // namespace hbtrack::continuation_detail
