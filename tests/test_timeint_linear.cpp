// Time integration of a linear single-dof oscillator against the analytic steady state, and the
// pieces of the steady-state machinery (initial state, period summary, detection, recording).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/period_summary.hpp"
#include "hbtrack/timeint/steady_state.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_timeint_linear {

using namespace hbtrack;
using cd = std::complex<double>;

namespace {

// m x'' + c x' + k x = F cos(w t): natural frequency 2, damping ratio 0.1, forced at 0.9 of
// resonance where the amplitude is sensitive to any frequency error of the scheme.
constexpr double kMass = 1.0, kDamping = 0.4, kStiffness = 4.0, kForce = 1.0, kOmega = 1.8;

StructuralModel oscillator() {
  StructuralModel m;
  m.dof_names = {"x"};
  m.mass = Eigen::MatrixXd::Constant(1, 1, kMass);
  m.damping = Eigen::MatrixXd::Constant(1, 1, kDamping);
  m.stiffness = Eigen::MatrixXd::Constant(1, 1, kStiffness);
  m.forcing = {HarmonicForce{1, Eigen::VectorXd::Constant(1, kForce), Eigen::VectorXd::Zero(1)}};
  return m;
}

// Complex amplitude X of x = Re(X e^{i w t}): F / (k - m w^2 + i c w).
cd analytic_response(double omega) { return kForce / cd(kStiffness - kMass * omega * omega, kDamping * omega); }

// The exact steady state of the HHT-alpha recurrence for e^{i w t_n} forcing (z-transform of
// the Newmark relations and of the alpha-weighted balance; see newmark_integrator.hpp).
cd discrete_hht_response(double omega, double h, double alpha) {
  const double beta = 0.25 * (1 - alpha) * (1 - alpha), gamma = 0.5 - alpha;
  const cd z = std::polar(1.0, omega * h);
  const cd v_per_a = h * ((1 - gamma) + gamma * z) / (z - 1.0);
  const cd x_per_a = (h * v_per_a + h * h * ((0.5 - beta) + beta * z)) / (z - 1.0);
  const cd weight = (1 + alpha) * z - alpha;
  return x_per_a * kForce * weight / (kMass * z + (kDamping * v_per_a + kStiffness * x_per_a) * weight);
}

const std::vector<OutputDof> kOutputs{{"x", 0, ""}};

// The transient left at convergence is about change / (1 - lambda), lambda = exp(-c T / 2m)
// = 0.50 per period here: a tight stroboscopic tolerance makes it negligible in comparisons to
// 1e-8 (it stays 100 times above the integrators' round-off, see steady_state.hpp).
SteadyStateOptions tight() {
  SteadyStateOptions o;
  o.tolerance = 1e-9;
  return o;
}

SteadyStateResult simulate_newmark(int steps, double alpha) {
  EquationOfMotion eom(oscillator(), {}, ParameterSet{}, kOmega);
  NewmarkOptions o;
  o.steps_per_period = steps;
  o.alpha = alpha;
  NewmarkIntegrator integrator(eom, o);
  return integrate_to_steady_state(integrator, rest_state(1), kOutputs, tight());
}

double relative_error(cd simulated, cd reference) { return std::abs(simulated - reference) / std::abs(reference); }

cd first_harmonic(const SteadyStateResult& r) {
  // a1 cos + b1 sin = Re((a1 - i b1) e^{i w t}).
  return {r.outputs[0].harmonics(1), -r.outputs[0].harmonics(2)};
}

}  // namespace

TEST(TimeIntegrationLinear, TrapezoidalRuleIsTheAnalyticResponseAtAWarpedFrequency) {
  // With alpha = 0 the discrete operators of d/dt act on e^{i w t} as i w~ with
  // w~ = (2/h) tan(w h / 2): the steady state is the analytic one at w~, an O((w h)^2) shift.
  const int steps = 64;
  const double h = 2 * std::numbers::pi / kOmega / steps;
  const SteadyStateResult r = simulate_newmark(steps, 0.0);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  const double warped = 2.0 / h * std::tan(kOmega * h / 2);
  EXPECT_LT(relative_error(first_harmonic(r), analytic_response(warped)), 1e-8);
  EXPECT_LT(relative_error(first_harmonic(r), discrete_hht_response(kOmega, h, 0.0)), 1e-8);
  // The distance to the continuous response is that warp, (w h)^2 / 12 = 8e-4 in frequency,
  // magnified by the slope of the resonance.
  const double warp_error = relative_error(analytic_response(warped), analytic_response(kOmega));
  EXPECT_NEAR(relative_error(first_harmonic(r), analytic_response(kOmega)), warp_error, 1e-8);
  EXPECT_LT(warp_error, 1e-2);
}

TEST(TimeIntegrationLinear, HhtAmplitudeConvergesAtSecondOrderToTheAnalyticOne) {
  const double alpha = NewmarkOptions{}.alpha;
  std::vector<double> errors;
  for (int steps : {64, 128}) {
    const SteadyStateResult r = simulate_newmark(steps, alpha);
    ASSERT_TRUE(r.converged) << r.stop_reason;
    const double h = 2 * std::numbers::pi / kOmega / steps;
    // The simulation is the recurrence's own steady state (phase included) ...
    EXPECT_LT(relative_error(first_harmonic(r), discrete_hht_response(kOmega, h, alpha)), 1e-8) << steps;
    // ... within the trapezoidal warp of the analytic amplitude, which alpha changes only by
    // O(alpha (w h)^2): a factor 1.5 covers it.
    const double warped = 2.0 / h * std::tan(kOmega * h / 2);
    const double bound = 1.5 * relative_error(analytic_response(warped), analytic_response(kOmega));
    const double amplitude_error = std::abs(r.outputs[0].first_harmonic() / std::abs(analytic_response(kOmega)) - 1.0);
    EXPECT_LT(amplitude_error, bound) << steps;
    errors.push_back(relative_error(first_harmonic(r), analytic_response(kOmega)));
  }
  // Second order: halving the step divides the error by 4.
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.2);
}

TEST(TimeIntegrationLinear, DormandPrinceAmplitudeMatchesTheAnalyticOne) {
  EquationOfMotion eom(oscillator(), {}, ParameterSet{}, kOmega);
  DormandPrinceIntegrator integrator(eom, DormandPrinceOptions{});
  const SteadyStateResult r = integrate_to_steady_state(integrator, rest_state(1), kOutputs, tight());
  ASSERT_TRUE(r.converged) << r.stop_reason;
  // Local tolerance 1e-9 per step over a few hundred steps per decay time: the steady state
  // carries about 1e-8; the dense output (4th order) interpolates the samples as well.
  EXPECT_LT(relative_error(first_harmonic(r), analytic_response(kOmega)), 1e-7);
  EXPECT_NEAR(r.outputs[0].max, std::abs(analytic_response(kOmega)), 1e-6);
  EXPECT_NEAR(r.outputs[0].min, -std::abs(analytic_response(kOmega)), 1e-6);
  EXPECT_NEAR(r.outputs[0].harmonics(0), 0.0, 1e-8);
}

TEST(TimeIntegrationLinear, StartingOnTheSteadyStateConvergesAtOnce) {
  EquationOfMotion eom(oscillator(), {}, ParameterSet{}, kOmega);
  DormandPrinceIntegrator integrator(eom, DormandPrinceOptions{});
  const cd x = analytic_response(kOmega);
  Eigen::VectorXd full(3);
  full << 0.0, x.real(), -x.imag();
  SteadyStateOptions options;
  const SteadyStateResult r = integrate_to_steady_state(integrator, state_from_harmonics(full, 1, 1, kOmega), kOutputs, options);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.periods, options.confirmations);
}

TEST(TimeIntegrationLinear, ABudgetTooShortIsReportedAsNotConverged) {
  EquationOfMotion eom(oscillator(), {}, ParameterSet{}, kOmega);
  NewmarkIntegrator integrator(eom, NewmarkOptions{});
  SteadyStateOptions options;
  options.max_periods = 3;
  const SteadyStateResult r = integrate_to_steady_state(integrator, rest_state(1), kOutputs, options);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.stop_reason, StopReason::max_periods);
  EXPECT_EQ(r.periods, 3);
  EXPECT_GT(r.last_change, options.tolerance);
}

TEST(TimeIntegrationLinear, RecordsTheLastPeriodsPhaseLockedToTheForcing) {
  EquationOfMotion eom(oscillator(), {}, ParameterSet{}, kOmega);
  NewmarkOptions o;
  o.steps_per_period = 32;
  NewmarkIntegrator integrator(eom, o);
  SteadyStateOptions options;
  options.max_periods = 10;
  options.record_periods = 3;
  const SteadyStateResult r = integrate_to_steady_state(integrator, rest_state(1), kOutputs, options);
  ASSERT_EQ(r.time.size(), 3 * 32);
  ASSERT_EQ(r.signals.rows(), 3 * 32);
  const double period = 2 * std::numbers::pi / kOmega;
  EXPECT_NEAR(r.time(0), 7 * period, 1e-12);
  EXPECT_NEAR(r.time(r.time.size() - 1), 10 * period - period / 32, 1e-12);
  EXPECT_DOUBLE_EQ(r.final_state.time, 10 * period);
  EXPECT_EQ(r.statistics.steps, 10 * 32);
  // Linear: one Newton iteration per step.
  EXPECT_EQ(r.statistics.newton_iterations, r.statistics.steps);
}

TEST(TimeIntegrationInitialState, HarmonicsGiveDisplacementAndVelocity) {
  // Two dofs, H = 2: x0 = 0.3 + cos(tau) - 2 sin(2 tau), x1 = -1 + 0.5 sin(tau) + 0.25 cos(2 tau).
  Eigen::VectorXd full(10);
  full << 0.6, -2.0,  // a0 (twice the mean)
      1.0, 0.0,       // a1
      0.0, 0.5,       // b1
      0.0, 0.25,      // a2
      -2.0, 0.0;      // b2
  const double omega = 3.0, t = 0.7, tau = omega * t;
  const MotionState s = state_from_harmonics(full, 2, 2, omega, t);
  EXPECT_DOUBLE_EQ(s.time, t);
  EXPECT_NEAR(s.x(0), 0.3 + std::cos(tau) - 2 * std::sin(2 * tau), 1e-14);
  EXPECT_NEAR(s.x(1), -1.0 + 0.5 * std::sin(tau) + 0.25 * std::cos(2 * tau), 1e-14);
  EXPECT_NEAR(s.v(0), omega * (-std::sin(tau) - 4 * std::cos(2 * tau)), 1e-13);
  EXPECT_NEAR(s.v(1), omega * (0.5 * std::cos(tau) - 0.5 * std::sin(2 * tau)), 1e-13);
  const MotionState rest = rest_state(2, 1.5);
  EXPECT_EQ(rest.x.norm() + rest.v.norm(), 0.0);
  EXPECT_EQ(rest.time, 1.5);
}

TEST(TimeIntegrationPeriodSummary, FourierCoefficientsInTheHbmLayout) {
  const int n = 64;
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) {
    const double tau = 2 * std::numbers::pi * i / n;
    x(i) = 0.5 + 2.0 * std::cos(tau) - 0.3 * std::sin(tau) + 0.1 * std::sin(3 * tau);
  }
  const PeriodSummary s = summarise_period(x, 3);
  ASSERT_EQ(s.harmonics.size(), 7);
  EXPECT_NEAR(s.harmonics(0), 1.0, 1e-13);  // a0 = twice the mean
  EXPECT_NEAR(s.harmonics(1), 2.0, 1e-13);
  EXPECT_NEAR(s.harmonics(2), -0.3, 1e-13);
  EXPECT_NEAR(s.first_harmonic(), std::hypot(2.0, 0.3), 1e-13);
  EXPECT_NEAR(s.harmonics(3), 0.0, 1e-13);
  EXPECT_NEAR(s.harmonics(6), 0.1, 1e-13);
  EXPECT_THROW(summarise_period(x.head(6), 3), std::invalid_argument);
}

TEST(TimeIntegrationPeriodSummary, ExtremesBetweenSamplesAreRefined) {
  // The peak falls half-way between samples, the worst case for the raw samples:
  // 1 - cos(pi / N) = 1.2e-3 at N = 64; on a cosine the parabola's error is O(h^4), h = 2 pi / N,
  // measured h^4 / 43.
  const int n = 64;
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = std::cos(2 * std::numbers::pi * (i + 0.5) / n);
  const PeriodSummary s = summarise_period(x, 1);
  EXPECT_NEAR(x.maxCoeff(), 1.0, 1.3e-3);
  const double h = 2 * std::numbers::pi / n;
  EXPECT_NEAR(s.max, 1.0, std::pow(h, 4) / 24);
  EXPECT_NEAR(s.min, -1.0, std::pow(h, 4) / 24);
}

}  // namespace hbtrack_tests::file_timeint_linear
