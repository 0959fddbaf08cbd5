#include "hbtrack/continuation/continuation.hpp"

#include <Eigen/LU>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

void ContinuationOptions::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v)) throw std::invalid_argument(std::string("continuation.") + name + ": must be > 0 and finite");
  };
  positive(step, "step");
  positive(step_min, "step_min");
  positive(step_max, "step_max");
  positive(tolerance, "tolerance");
  if (step_min > step) throw std::invalid_argument("continuation.step_min: must be <= step");
  if (step > step_max) throw std::invalid_argument("continuation.step: must be <= step_max");
  if (max_points < 1) throw std::invalid_argument("continuation.max_points: must be >= 1");
  if (max_iterations < 1 || max_iterations > 1000) throw std::invalid_argument("continuation.max_iterations: must be in [1, 1000]");
  if (target_iterations < 1) throw std::invalid_argument("continuation.target_iterations: must be >= 1");
  if (!(max_angle > 0) || max_angle > 3.14159) throw std::invalid_argument("continuation.max_angle: must be in (0, pi]");
  if (predictor != "tangent" && predictor != "secant")
    throw std::invalid_argument("continuation.predictor: must be tangent or secant, got '" + predictor + "'");
  if (corrector != "pseudo_arclength" && corrector != "hypersphere")
    throw std::invalid_argument("continuation.corrector: must be pseudo_arclength or hypersphere, got '" + corrector + "'");
  if (wall_time_limit < 0) throw std::invalid_argument("continuation.wall_time_limit: must be >= 0");
}

bool ContinuationResult::success() const {
  return summary.stop_reason == "reached_end" || summary.stop_reason == "max_points";
}

namespace {

double inf_norm(const VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

// Scaled-coordinate view of the problem: X = [u ./ su; lambda / sl].
struct Scaled {
  ContinuationProblem& problem;
  VectorXd su;
  double sl;
  double rtol;
  int m;
  VectorXd r, r_lambda;
  MatrixXd jac;
  int jacobian_evaluations = 0;

  // Re-scales scaled vectors after the unknown scale changed to that of the point u.
  void rescale(const VectorXd& u, std::initializer_list<VectorXd*> points, VectorXd& tangent_vec) {
    const VectorXd new_su = problem.unknown_scale(u);
    if (new_su == su) return;
    for (VectorXd* p : points)
      if (p->size() == m + 1) p->head(m) = p->head(m).cwiseProduct(su).cwiseQuotient(new_su);
    tangent_vec.head(m) = tangent_vec.head(m).cwiseProduct(su).cwiseQuotient(new_su);
    tangent_vec.normalize();
    su = new_su;
  }
  VectorXd pack(const VectorXd& u, double lambda) const {
    VectorXd x(m + 1);
    x.head(m) = u.cwiseQuotient(su);
    x(m) = lambda / sl;
    return x;
  }
  VectorXd unknowns(const VectorXd& x) const { return x.head(m).cwiseProduct(su); }
  double parameter(const VectorXd& x) const { return x(m) * sl; }
  // Evaluates R, dR/dX (scaled) at x; returns the relative residual.
  double evaluate(const VectorXd& x) {
    problem.evaluate(unknowns(x), parameter(x), r, &jac, &r_lambda);
    ++jacobian_evaluations;
    return inf_norm(r) / rtol;
  }
  // The bordered matrix [J diag(su), r_lambda sl; row].
  MatrixXd bordered(const VectorXd& row) const {
    MatrixXd a(m + 1, m + 1);
    a.topLeftCorner(m, m) = jac * su.asDiagonal();
    a.topRightCorner(m, 1) = r_lambda * sl;
    a.row(m) = row.transpose();
    return a;
  }
  // Unit tangent of the branch at the last evaluated point, oriented along `reference`.
  VectorXd tangent(const VectorXd& reference) const {
    Eigen::PartialPivLU<MatrixXd> lu(bordered(reference));
    VectorXd rhs = VectorXd::Zero(m + 1);
    rhs(m) = 1.0;
    VectorXd t = lu.solve(rhs);
    t.normalize();
    if (t.dot(reference) < 0) t = -t;
    return t;
  }
};

}  // namespace

int newton_at_fixed_parameter(ContinuationProblem& problem, VectorXd& u, double lambda, double tolerance,
                              int max_iterations) {
  VectorXd r, r_lambda;
  MatrixXd jac;
  const double scale = problem.residual_scale();
  for (int it = 0; it <= max_iterations; ++it) {
    problem.evaluate(u, lambda, r, &jac, &r_lambda);
    if (!r.allFinite()) return -1;
    if (inf_norm(r) <= tolerance * scale) return it;
    if (it == max_iterations) break;
    const VectorXd du = jac.partialPivLu().solve(-r);
    if (!du.allFinite()) return -1;
    u += du;
  }
  return -1;
}

ContinuationResult continue_branch(ContinuationProblem& problem, const VectorXd& u0, double lambda_start,
                                   double lambda_end, const ContinuationOptions& options, const PointObserver& observer) {
  options.validate();
  const auto clock_start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count(); };
  ContinuationResult result;
  ContinuationSummary& summary = result.summary;
  Scaled s{problem, problem.unknown_scale(u0), problem.parameter_scale(), problem.residual_scale(), problem.size(), {}, {}, {}};
  const int m = s.m;
  const double direction = lambda_end >= lambda_start ? 1.0 : -1.0;

  auto finish = [&](const std::string& reason) {
    summary.stop_reason = reason;
    summary.points = static_cast<int>(result.points.size());
    summary.jacobian_evaluations = s.jacobian_evaluations;
    summary.wall_s = elapsed();
    return result;
  };
  auto accept = [&](BranchPoint p) {
    result.points.push_back(std::move(p));
    const int index = static_cast<int>(result.points.size()) - 1;
    return !observer || observer(result.points.back(), index);
  };

  // First point: Newton at fixed lambda_start.
  VectorXd u = u0;
  const int first_iterations = newton_at_fixed_parameter(problem, u, lambda_start, options.tolerance, 3 * options.max_iterations);
  if (first_iterations < 0) return finish("no_convergence_at_start");
  summary.newton_iterations += first_iterations;
  s.su = problem.unknown_scale(u);
  VectorXd x = s.pack(u, lambda_start);
  s.evaluate(x);
  VectorXd lambda_axis = VectorXd::Zero(m + 1);
  lambda_axis(m) = direction;
  VectorXd t = s.tangent(lambda_axis);
  if (t(m) * direction < 0) t = -t;
  if (!accept({u, lambda_start, t, first_iterations, 0.0})) return finish("interrupted");

  double ds = options.step;
  VectorXd x_prev_prev;  // for the secant predictor
  while (true) {
    if (static_cast<int>(result.points.size()) >= options.max_points) return finish("max_points");
    if (options.wall_time_limit > 0 && elapsed() > options.wall_time_limit) return finish("wall_time_limit");

    // Predictor.
    VectorXd direction_vec = t;
    if (options.predictor == "secant" && x_prev_prev.size() == m + 1) {
      direction_vec = x - x_prev_prev;
      direction_vec.normalize();
    }
    const VectorXd prediction = x + ds * direction_vec;
    VectorXd y = prediction;

    // Corrector: Newton on [R; P] = 0.
    bool converged = false;
    int iterations = 0;
    for (int it = 0; it <= options.max_iterations; ++it) {
      const double residual = s.evaluate(y);
      const VectorXd d = y - x;
      double p;
      VectorXd p_row;
      if (options.corrector == "hypersphere") {
        p = d.squaredNorm() - ds * ds;
        p_row = 2.0 * d;
        if (it == 0 && p_row.norm() == 0.0) p_row = direction_vec;
      } else {
        p = direction_vec.dot(d) - ds;
        p_row = direction_vec;
      }
      if (!std::isfinite(residual)) break;
      if (residual <= options.tolerance && std::abs(p) <= 1e-8 * ds * std::max(1.0, ds)) {
        converged = true;
        iterations = it;
        break;
      }
      if (it == options.max_iterations) break;
      VectorXd rhs(m + 1);
      rhs.head(m) = -s.r;
      rhs(m) = -p;
      const VectorXd dy = s.bordered(p_row).partialPivLu().solve(rhs);
      if (!dy.allFinite()) break;
      y += dy;
      ++summary.newton_iterations;
    }
    // Reject a corrector that did not converge, went back along the branch, jumped away from
    // the prediction or turned too sharply; the Jacobian at y is the one just evaluated.
    // At the smallest step a corner is real (a nonsmooth law kinks the branch): go through it.
    const bool smallest_step = ds <= 2 * options.step_min;
    VectorXd t_new;
    bool accepted = converged && (y - x).dot(t) > 0 && (smallest_step || (y - prediction).norm() <= ds);
    if (accepted) {
      t_new = s.tangent(t);
      accepted = smallest_step || std::acos(std::clamp(t.dot(t_new), -1.0, 1.0)) <= options.max_angle;
    }
    if (!accepted) {
      if (!converged) ++summary.failed_steps;
      ++summary.step_halvings;
      ds *= 0.5;
      if (ds < options.step_min) return finish(converged ? "step_size_underflow_on_curvature" : "step_size_underflow");
      continue;
    }

    const double arc = (y - x).norm();
    if (t(m) * t_new(m) < 0) {
      // The lambda component of the tangent changed sign: a limit point between the two points.
      // Record it at the point where lambda is extreme (located precisely in a later step).
      const bool was_rising = t(m) > 0;
      const bool new_is_extreme = was_rising ? s.parameter(y) >= s.parameter(x) : s.parameter(y) <= s.parameter(x);
      const int index = static_cast<int>(result.points.size()) - (new_is_extreme ? 0 : 1);
      result.special_points.push_back({"LP", index, false, new_is_extreme ? s.parameter(y) : s.parameter(x),
                                       new_is_extreme ? s.unknowns(y) : s.unknowns(x)});
    }
    x_prev_prev = x;
    x = y;
    t = t_new;
    const double lambda = s.parameter(x);
    const bool beyond_end = (lambda - lambda_end) * direction >= 0;
    if (beyond_end) {
      // Land exactly on lambda_end, interpolating the last step.
      const double lam_prev = s.parameter(x_prev_prev);
      const double f = (lambda_end - lam_prev) / (lambda - lam_prev);
      VectorXd u_end = s.unknowns(x_prev_prev + f * (x - x_prev_prev));
      const int it = newton_at_fixed_parameter(problem, u_end, lambda_end, options.tolerance, options.max_iterations);
      if (it >= 0) {
        summary.newton_iterations += it;
        if (!accept({u_end, lambda_end, t, it, arc * f})) return finish("interrupted");
        return finish("reached_end");
      }
    }
    if (!accept({s.unknowns(x), lambda, t, iterations, arc})) return finish("interrupted");
    if (beyond_end) return finish("reached_end");
    // The branch turned back and passed below the start of the range.
    if ((lambda - lambda_start) * direction < 0) return finish("left_range");

    s.rescale(s.unknowns(x), {&x, &x_prev_prev}, t);
    const double factor = iterations == 0 ? 1.5 : std::clamp(static_cast<double>(options.target_iterations) / iterations, 0.5, 1.5);
    ds = std::min(ds * factor, options.step_max);
  }
}

}  // namespace hbtrack
