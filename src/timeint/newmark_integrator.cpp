#include "hbtrack/timeint/newmark_integrator.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hbtrack {

void NewmarkOptions::validate() const {
  if (steps_per_period < 1) throw std::invalid_argument("steps_per_period: must be >= 1, got " + std::to_string(steps_per_period));
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0))
    throw std::invalid_argument("alpha: must lie in [-1/3, 0] (unconditional stability), got " + std::to_string(alpha));
  if (!(newton_tolerance > 0) || !std::isfinite(newton_tolerance)) throw std::invalid_argument("newton_tolerance: must be > 0");
  if (max_newton_iterations < 1) throw std::invalid_argument("max_newton_iterations: must be >= 1");
  if (max_refinements < 0 || max_refinements > 30) throw std::invalid_argument("max_refinements: must lie in [0, 30]");
  if (element_steps < 0) throw std::invalid_argument("element_steps: must be >= 0 (0: steps_per_period)");
}

NewmarkIntegrator::NewmarkIntegrator(EquationOfMotion& equation, NewmarkOptions options)
    : equation_(equation), options_((options.validate(), options)) {
  beta_ = 0.25 * (1.0 - options_.alpha) * (1.0 - options_.alpha);
  gamma_ = 0.5 - options_.alpha;
  start(MotionState{0.0, Eigen::VectorXd::Zero(equation_.dofs()), Eigen::VectorXd::Zero(equation_.dofs())});
}

void NewmarkIntegrator::internal_force(double time, const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& q,
                                       bool with_tangents) {
  equation_.nonlinear_force(time, x, v, f_nl_, with_tangents ? &df_dx_ : nullptr, with_tangents ? &df_dv_ : nullptr);
  ++statistics_.force_evaluations;
  q.noalias() = equation_.damping() * v;
  q.noalias() += equation_.stiffness() * x;
  q += f_nl_;
}

void NewmarkIntegrator::start(const MotionState& initial) {
  const int n = equation_.dofs();
  if (initial.x.size() != n || initial.v.size() != n) throw std::invalid_argument("NewmarkIntegrator::start: state size");
  state_ = initial;
  start_time_ = initial.time;
  period_index_ = 0;
  statistics_ = {};
  failure_ = {};
  equation_.start_history(initial.time, initial.history);
  state_.history = equation_.history();
  // The initial acceleration satisfies the equation of motion at t0.
  internal_force(state_.time, state_.x, state_.v, internal_, true);
  df_dx_at_state_ = df_dx_;
  df_dv_at_state_ = df_dv_;
  equation_.external_force(state_.time, external_);
  acceleration_ = equation_.mass().llt().solve(external_ - internal_);
}

bool NewmarkIntegrator::step(double t_next, int depth) {
  if (!solve_step(t_next)) return false;
  if (depth < options_.max_refinements && needs_refinement(t_next - state_.time)) {
    const double middle = 0.5 * (state_.time + t_next);
    return step(middle, depth + 1) && step(t_next, depth + 1);
  }
  commit_step(t_next);
  return true;
}

// The fastest rate the elements' tangents impose, in rad/s: sqrt(|df/dx| / m) for a
// stiffness, |df/dv| / m for a damping, entry by entry with m = sqrt(M_ii M_jj).
double NewmarkIntegrator::element_rate(const Eigen::MatrixXd& df_dx, const Eigen::MatrixXd& df_dv) const {
  const Eigen::MatrixXd& mass = equation_.mass();
  double rate = 0;
  for (Eigen::Index j = 0; j < mass.cols(); ++j)
    for (Eigen::Index i = 0; i < mass.rows(); ++i) {
      const double m = std::sqrt(mass(i, i) * mass(j, j));
      rate = std::max({rate, std::sqrt(std::abs(df_dx(i, j)) / m), std::abs(df_dv(i, j)) / m});
    }
  return rate;
}

bool NewmarkIntegrator::needs_refinement(double h) {
  if (!equation_.has_nonlinear_elements()) return false;
  // The elements get the resolution the forcing has: omega_t h <= omega h_base = 2 pi / N (or
  // the resolution asked of them, 2 pi / element_steps).
  const int resolution = options_.element_steps > 0 ? options_.element_steps : options_.steps_per_period;
  const double limit = equation_.omega() * equation_.period() / resolution;
  if (std::max(element_rate(df_dx_at_state_, df_dv_at_state_), element_rate(df_dx_, df_dv_)) * h > limit) return true;
  // A contact shorter than the step leaves both ends open: look at the middle too (cubic
  // Hermite interpolation of the step).
  mid_x_ = 0.5 * (state_.x + x_) + (h / 8.0) * (state_.v - v_);
  mid_v_ = 0.5 * (state_.v + v_) + (h / 8.0) * (acceleration_ - a_);
  equation_.nonlinear_force(state_.time + 0.5 * h, mid_x_, mid_v_, mid_f_, &mid_dx_, &mid_dv_);
  ++statistics_.force_evaluations;
  return element_rate(mid_dx_, mid_dv_) * h > limit;
}

bool NewmarkIntegrator::solve_step(double t_next) {
  const double alpha = options_.alpha, h = t_next - state_.time;
  const Eigen::MatrixXd& mass = equation_.mass();
  const Eigen::VectorXd& x_n = state_.x;
  const Eigen::VectorXd& v_n = state_.v;
  const Eigen::VectorXd& a_n = acceleration_;
  equation_.external_force(t_next, f_next_);
  // Everything of the HHT balance that does not depend on x_{n+1}.
  load_ = (1.0 + alpha) * f_next_ - alpha * external_ + alpha * internal_;
  // d a / d x and d v / d x along the Newmark relations at fixed x_n, v_n, a_n.
  const double a_per_x = 1.0 / (beta_ * h * h), v_per_x = gamma_ / (beta_ * h);

  // Newton works on the end-of-step acceleration and the Newmark relations give x and v from
  // it: recovering a from x instead, (x - x_n - h v_n) / (beta h^2), would cancel digits when
  // the step is small. The tangent is the usual displacement-form one, dR/dx.
  a_ = a_n;  // predictor: constant acceleration
  bool at_round_off = false;
  for (int iteration = 0;; ++iteration) {
    x_ = x_n + h * v_n + (h * h) * ((0.5 - beta_) * a_n + beta_ * a_);
    v_ = v_n + h * ((1.0 - gamma_) * a_n + gamma_ * a_);
    internal_force(t_next, x_, v_, q_, true);
    inertia_.noalias() = mass * a_;
    residual_ = inertia_ + (1.0 + alpha) * q_ - load_;
    // Relative to the largest term of the balance: the units of the model do not matter.
    const double reference =
        std::max({inertia_.lpNorm<Eigen::Infinity>(), (1.0 + alpha) * q_.lpNorm<Eigen::Infinity>(), load_.lpNorm<Eigen::Infinity>()});
    const double error = residual_.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(error)) {
      failure_ = {StopReason::diverged, "non-finite forces at t = " + std::to_string(t_next)};
      return false;
    }
    if (error <= options_.newton_tolerance * reference || at_round_off) break;
    if (iteration == options_.max_newton_iterations) {
      failure_ = {StopReason::newton_failure, "Newton did not converge in " + std::to_string(iteration) +
                                                  " iterations at t = " + std::to_string(t_next) + " (residual " +
                                                  std::to_string(error / reference) + " of the largest force)"};
      return false;
    }
    tangent_ = a_per_x * mass + (1.0 + alpha) * (equation_.stiffness() + df_dx_ + v_per_x * (equation_.damping() + df_dv_));
    lu_.compute(tangent_);
    dx_ = lu_.solve(-residual_);
    a_ += a_per_x * dx_;
    ++statistics_.newton_iterations;
    // An update at the level of round-off cannot reduce the residual further.
    at_round_off = dx_.lpNorm<Eigen::Infinity>() <= 8.0 * std::numeric_limits<double>::epsilon() * x_.lpNorm<Eigen::Infinity>();
  }
  return true;
}

void NewmarkIntegrator::commit_step(double t_next) {
  // x_, v_ and the tangents belong to the last evaluation, the accepted one.
  state_.time = t_next;
  state_.x = x_;
  state_.v = v_;
  equation_.commit_history(t_next, x_);
  state_.history = equation_.history();
  acceleration_ = a_;
  internal_ = q_;
  external_ = f_next_;
  df_dx_at_state_ = df_dx_;
  df_dv_at_state_ = df_dv_;
  ++statistics_.steps;
}

bool NewmarkIntegrator::advance_period(const SampleObserver& observe) {
  const double period = equation_.period();
  const int steps = options_.steps_per_period;
  const double t0 = start_time_ + static_cast<double>(period_index_) * period;
  for (int i = 0; i < steps; ++i) {
    if (observe) observe(i, state_);
    // Step ends from the period index, so rounding does not accumulate over many periods.
    const double t_next = i + 1 == steps ? start_time_ + static_cast<double>(period_index_ + 1) * period : t0 + (i + 1) * (period / steps);
    if (!step(t_next, 0)) return false;
  }
  ++period_index_;
  return true;
}

}  // namespace hbtrack
