#pragma once
// Implicit Newmark integration in its HHT-alpha form (Hilber, Hughes & Taylor 1977), base step
// h = T / steps_per_period, with Newton iterations on the end-of-step balance using the
// elements' analytic tangents:
//   M a_{n+1} + (1 + alpha) q(x_{n+1}, v_{n+1}) - alpha q_n = (1 + alpha) f_ext(t_{n+1}) - alpha f_ext(t_n),
//   q = C v + K x + f_nl(x, v),  beta = (1 - alpha)^2 / 4,  gamma = 1/2 - alpha,
//   tangent dR/dx = M / (beta h^2) + (1 + alpha) (K + df/dx + gamma / (beta h) (C + df/dv)).
// For -1/3 <= alpha <= 0 it is second-order accurate and unconditionally stable for linear
// systems: linear modes far above the forcing (a fine FE mesh, a stiff appendage) cost nothing,
// where an explicit method must resolve them at every step. alpha < 0 damps what the step cannot
// resolve and leaves resolved motion almost untouched: with the default alpha = -0.05 a mode of
// frequency w_m gets the algorithmic damping ratio 0.0056 (w_m h)^3 (3e-4 at 16 steps per
// period of the mode, 5e-6 at 64) and the period error (w_m h)^2 / 12, while a mode far beyond
// the step loses 10 % of its amplitude per step (spectral radius (1 + alpha) / (1 - alpha)).
//
// Stiff elements are another matter: unconditional stability does not survive a penalty contact
// that opens and closes inside a step (the classical energy gain of the trapezoidal family at
// impacts). With a fixed step the two-dof contact example with k = 500 never settles to a
// periodic motion and with k = 50000 it blows up (docs/time-integration.md). So a step is halved,
// up to max_refinements times, while an element's tangent is not resolved as finely as the
// forcing, omega_t h > 2 pi / steps_per_period (element_steps if set) with omega_t = sqrt(|df/dx| / m) or |df/dv| / m,
// checked at the start, end and middle of the step: contact phases get small steps, the rest of
// the period keeps the base step, and the samples stay on the base grid.
// When to use which integrator: docs/time-integration.md.
#include <Eigen/Dense>

#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/time_integrator.hpp"

namespace hbtrack {

struct NewmarkOptions {
  int steps_per_period = 256;
  double alpha = -0.05;             // HHT alpha in [-1/3, 0]; 0 is the trapezoidal rule
  double newton_tolerance = 1e-10;  // ||residual||_inf <= tolerance * the largest force term
  int max_newton_iterations = 30;
  int max_refinements = 10;  // halvings of a step where the elements are stiff (0: fixed step)
  // Steps per period of the elements' fastest rate omega_t that the halvings aim for: a step
  // is halved while omega_t h > 2 pi / element_steps. 0: steps_per_period (the elements
  // resolved as finely as the forcing).
  int element_steps = 0;
  void validate() const;  // throws std::invalid_argument naming the field
};

class NewmarkIntegrator final : public TimeIntegrator {
 public:
  // Keeps a reference to `equation`, which must outlive the integrator.
  NewmarkIntegrator(EquationOfMotion& equation, NewmarkOptions options);

  std::string method() const override { return "newmark"; }
  const EquationOfMotion& equation() const override { return equation_; }
  int samples_per_period() const override { return options_.steps_per_period; }
  void start(const MotionState& initial) override;
  bool advance_period(const SampleObserver& observe) override;
  const MotionState& state() const override { return state_; }
  const IntegrationStatistics& statistics() const override { return statistics_; }
  const NewmarkOptions& options() const { return options_; }

 private:
  // One step from state_ to t_next, split in halves where the tangent jumps (depth: halvings so far).
  bool step(double t_next, int depth);
  // Newton on the end-of-step balance; leaves the end state in x_, v_, a_, q_ and its tangents.
  bool solve_step(double t_next);
  void commit_step(double t_next);
  bool needs_refinement(double h);
  double element_rate(const Eigen::MatrixXd& df_dx, const Eigen::MatrixXd& df_dv) const;
  // q = C v + K x + f_nl(x, v), with the tangents when asked.
  void internal_force(double time, const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& q, bool with_tangents);

  EquationOfMotion& equation_;
  NewmarkOptions options_;
  double beta_, gamma_;
  long period_index_ = 0;
  double start_time_ = 0;
  MotionState state_;
  IntegrationStatistics statistics_;
  // Acceleration, internal and external force at the current instant (the HHT weights need them).
  Eigen::VectorXd acceleration_, internal_, external_;
  Eigen::MatrixXd df_dx_at_state_, df_dv_at_state_;
  // Workspace of one step.
  Eigen::VectorXd x_, v_, a_, q_, f_next_, load_, inertia_, residual_, dx_, f_nl_;
  Eigen::MatrixXd df_dx_, df_dv_, tangent_;
  Eigen::VectorXd mid_x_, mid_v_, mid_f_;
  Eigen::MatrixXd mid_dx_, mid_dv_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace hbtrack
