#pragma once
// Adaptive explicit integration with the Dormand-Prince 5(4) pair (Boost.odeint
// runge_kutta_dopri5 under step control, with its 4th-order dense output for the samples) on
// the first-order form
//   y = [x; v],  y' = [v; M^-1 (f_ext(t) - C v - K x - f_nl(x, v))],  M^-1 precomputed (LLT).
// Each step is accurate to the tolerances and no Jacobian is needed. Being explicit, its step is
// bounded by stability, about 3.3 / w_max for the highest frequency present at that instant: a
// stiff penalty contact only shortens the steps while it is closed (the two-dof example with a
// contact 10^4 times stiffer: 341 steps per period instead of 292), but a stiff linear mode
// shortens every step (a 1000 rad/s appendage: 3900 steps per period, 27 times the force
// evaluations of NewmarkIntegrator).
// Use it for small models, smooth or contact nonlinearities and tight reference solutions; the
// implicit NewmarkIntegrator when the model has linear modes far above the response
// (docs/time-integration.md).
#include <Eigen/Dense>
#include <memory>

#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/time_integrator.hpp"

namespace hbtrack {

struct DormandPrinceOptions {
  int samples_per_period = 256;       // reported instants per period (the step adapts)
  double relative_tolerance = 1e-9;   // per step, on each state component
  double absolute_tolerance = 1e-12;  // per step, in the model's units (displacement, velocity)
  void validate() const;              // throws std::invalid_argument naming the field
};

class DormandPrinceIntegrator final : public TimeIntegrator {
 public:
  // Keeps a reference to `equation`, which must outlive the integrator.
  DormandPrinceIntegrator(EquationOfMotion& equation, DormandPrinceOptions options);
  ~DormandPrinceIntegrator() override;

  std::string method() const override { return "dopri5"; }
  const EquationOfMotion& equation() const override { return equation_; }
  int samples_per_period() const override { return options_.samples_per_period; }
  void start(const MotionState& initial) override;
  bool advance_period(const SampleObserver& observe) override;
  const MotionState& state() const override { return state_; }
  const IntegrationStatistics& statistics() const override { return statistics_; }
  const DormandPrinceOptions& options() const { return options_; }

 private:
  struct Stepper;             // the odeint stepper, kept out of this header
  bool advance_to(double t);  // steps until the dense output covers t
  void interpolate(double t, MotionState& out);

  EquationOfMotion& equation_;
  DormandPrinceOptions options_;
  Eigen::MatrixXd inverse_mass_;
  std::unique_ptr<Stepper> stepper_;
  long period_index_ = 0;
  double start_time_ = 0;
  MotionState state_, sample_;
  IntegrationStatistics statistics_;
};

}  // namespace hbtrack
