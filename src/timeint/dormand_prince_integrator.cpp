#include "hbtrack/timeint/dormand_prince_integrator.hpp"

#include <Eigen/Cholesky>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace hbtrack {

namespace odeint = boost::numeric::odeint;
using OdeState = std::vector<double>;

void DormandPrinceOptions::validate() const {
  if (samples_per_period < 1) throw std::invalid_argument("samples_per_period: must be >= 1, got " + std::to_string(samples_per_period));
  if (!(relative_tolerance > 0) || !std::isfinite(relative_tolerance)) throw std::invalid_argument("relative_tolerance: must be > 0");
  if (!(absolute_tolerance > 0) || !std::isfinite(absolute_tolerance)) throw std::invalid_argument("absolute_tolerance: must be > 0");
}

// The controlled Dormand-Prince 5(4) stepper with dense output, and the right-hand side of the
// first-order form.
struct DormandPrinceIntegrator::Stepper {
  using DenseStepper = odeint::result_of::make_dense_output<odeint::runge_kutta_dopri5<OdeState>>::type;
  DenseStepper dense;
  OdeState y;  // start state for initialize, then interpolation target
  // Workspace of the right-hand side.
  Eigen::VectorXd x, v, f_nl, f_ext, force;

  explicit Stepper(const DormandPrinceOptions& o)
      : dense(odeint::make_dense_output(o.absolute_tolerance, o.relative_tolerance, odeint::runge_kutta_dopri5<OdeState>())) {}
};

DormandPrinceIntegrator::DormandPrinceIntegrator(EquationOfMotion& equation, DormandPrinceOptions options)
    : equation_(equation), options_((options.validate(), options)), stepper_(std::make_unique<Stepper>(options_)) {
  const int n = equation_.dofs();
  inverse_mass_ = equation_.mass().llt().solve(Eigen::MatrixXd::Identity(n, n));
  start(MotionState{0.0, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)});
}

DormandPrinceIntegrator::~DormandPrinceIntegrator() = default;

void DormandPrinceIntegrator::start(const MotionState& initial) {
  const int n = equation_.dofs();
  if (initial.x.size() != n || initial.v.size() != n) throw std::invalid_argument("DormandPrinceIntegrator::start: state size");
  state_ = initial;
  start_time_ = initial.time;
  period_index_ = 0;
  statistics_ = {};
  failure_ = {};
  OdeState& y = stepper_->y;
  equation_.start_history(initial.time, initial.history);
  state_.history = equation_.history();
  y.resize(static_cast<size_t>(2 * n));
  Eigen::Map<Eigen::VectorXd>(y.data(), n) = initial.x;
  Eigen::Map<Eigen::VectorXd>(y.data() + n, n) = initial.v;
  // A first step of 1/1000 period; the controller adapts it within a few steps.
  stepper_->dense.initialize(y, initial.time, 1e-3 * equation_.period());
}

bool DormandPrinceIntegrator::advance_to(double t) {
  const int n = equation_.dofs();
  Stepper& s = *stepper_;
  auto right_hand_side = [&](const OdeState& y, OdeState& dydt, double time) {
    const Eigen::Map<const Eigen::VectorXd> x(y.data(), n), v(y.data() + n, n);
    s.x = x;
    s.v = v;
    equation_.nonlinear_force(time, s.x, s.v, s.f_nl);
    equation_.external_force(time, s.f_ext);
    s.force = s.f_ext - s.f_nl;
    s.force.noalias() -= equation_.damping() * s.v;
    s.force.noalias() -= equation_.stiffness() * s.x;
    Eigen::Map<Eigen::VectorXd>(dydt.data(), n) = s.v;
    Eigen::Map<Eigen::VectorXd>(dydt.data() + n, n).noalias() = inverse_mass_ * s.force;
    ++statistics_.force_evaluations;
  };
  try {
    while (s.dense.current_time() < t) {
      s.dense.do_step(right_hand_side);
      ++statistics_.steps;
      const OdeState& y = s.dense.current_state();
      if (!Eigen::Map<const Eigen::VectorXd>(y.data(), 2 * n).allFinite()) {
        failure_ = {StopReason::diverged, "non-finite state at t = " + std::to_string(s.dense.current_time())};
        return false;
      }
      // The step is accepted: history elements move on to its end (every stage of the step,
      // rejected tries included, return-mapped from its start).
      if (equation_.history_size() > 0) equation_.commit_history(s.dense.current_time(), Eigen::Map<const Eigen::VectorXd>(y.data(), n));
    }
  } catch (const std::exception& e) {
    // odeint gives up after repeated step-size reductions (step_adjustment_error).
    failure_ = {StopReason::integration_failure, std::string("Dormand-Prince step failed: ") + e.what()};
    return false;
  }
  return true;
}

void DormandPrinceIntegrator::interpolate(double t, MotionState& out) {
  const int n = equation_.dofs();
  OdeState& y = stepper_->y;
  stepper_->dense.calc_state(t, y);
  out.time = t;
  out.x = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
  out.v = Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
}

bool DormandPrinceIntegrator::advance_period(const SampleObserver& observe) {
  const double period = equation_.period();
  const int samples = options_.samples_per_period;
  const double t0 = start_time_ + static_cast<double>(period_index_) * period;
  // The period's start is already known (no step covers it before the first one).
  if (observe) observe(0, state_);
  for (int i = 1; i < samples; ++i) {
    const double t = t0 + i * (period / samples);
    if (!advance_to(t)) return false;
    if (observe) {
      interpolate(t, sample_);
      observe(i, sample_);
    }
  }
  // The integration goes on from the stepper's own state; the period end is interpolated.
  const double t_end = start_time_ + static_cast<double>(period_index_ + 1) * period;
  if (!advance_to(t_end)) return false;
  interpolate(t_end, state_);
  // The internal variables at the last accepted step, which may end a little after t_end.
  state_.history = equation_.history();
  ++period_index_;
  return true;
}

}  // namespace hbtrack
