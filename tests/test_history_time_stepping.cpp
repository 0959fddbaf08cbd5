// History elements (Jenkins, Iwan, frictional contact) in the time domain: the equation of
// motion's tangents with committed slider states, time integration started on a harmonic-balance
// orbit (NLvib's three oscillators), and the monodromy multipliers against Hill's.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/elements/elastic_dry_friction.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/iwan.hpp"
#include "hbtrack/elements/tip_contact.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/stability/hill.hpp"
#include "hbtrack/stability/monodromy.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_history_time_stepping {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

template <class Element>
std::shared_ptr<Element> with_properties(std::shared_ptr<Element> e, std::vector<int> dofs, const std::vector<double>& props) {
  e->dofs = std::move(dofs);
  for (double p : props) e->properties.push_back(ParameterBinding::constant(p));
  return e;
}

// Three dofs: a Jenkins element on x1, an Iwan joint between x2 and x1, a frictional contact
// [normal x3, tangential x2], a stick-slip tip contact [radial x3, theta x2, z x1] on a turning
// casing, a frictional contact in two directions [normal x3, tangential x1, x2].
ElementList history_elements() {
  auto jenkins = std::make_shared<ElasticDryFriction>();
  jenkins->weights = VectorXd::Ones(1);
  auto iwan = std::make_shared<Iwan>(8);
  iwan->weights = (VectorXd(2) << 1.0, -1.0).finished();
  return {with_properties(jenkins, {0}, {20.0, 1.0}), with_properties(iwan, {1, 0}, {1.0, 30.0, -0.4, 0.5}),
          with_properties(std::make_shared<FrictionalContact>(), {2, 1}, {5.0, 20.0, 0.4, 1.0}),
          with_properties(std::make_shared<TipContact>(ContactLawKind::polynomial, TipFriction::stick_slip), {2, 1, 0},
                          {5.0, 0.05, 0.2, 0.3, 0.2, 1.0, 0.0, 15.0}),
          with_properties(std::make_shared<FrictionalContact>(ContactFormulation::penalty, 2), {2, 0, 1}, {5.0, 20.0, 0.4, 1.0})};
}

}  // namespace

TEST(HistoryTimeStepping, TangentsWithCommittedStatesMatchFiniteDifferences) {
  // From a committed state the return mapping is piecewise affine in x: central differences
  // are exact up to round-off / h (~1e-9 relative) away from a stick/slip boundary, which these
  // states keep further than h from.
  EquationOfMotion eom(test::chain_between_walls(3, 1), history_elements(), ParameterSet(), 1.0);
  ASSERT_EQ(eom.history_size(), 1 + 9 + 1 + 2 + 2);
  const VectorXd v = VectorXd::Zero(3);
  struct Case {
    const char* name;
    VectorXd committed, trial;
  };
  const std::vector<Case> cases{{"stick", (VectorXd(3) << 0.01, 0.02, -0.01).finished(), (VectorXd(3) << 0.012, 0.015, -0.02).finished()},
                                {"slip", (VectorXd(3) << 0.2, -0.3, 0.1).finished(), (VectorXd(3) << 0.35, -0.5, 0.15).finished()},
                                {"separation", (VectorXd(3) << 0.2, -0.3, -0.1).finished(), (VectorXd(3) << 0.12, 0.2, -0.3).finished()}};
  for (const Case& c : cases) {
    eom.start_history(0.0, VectorXd());
    eom.commit_history(0.1, c.committed);
    VectorXd f;
    MatrixXd df_dx;
    eom.nonlinear_force(0.2, c.trial, v, f, &df_dx);
    const MatrixXd fd = test::fd_jacobian(
        [&](const VectorXd& y) {
          VectorXd fy;
          eom.nonlinear_force(0.2, y, v, fy);
          return fy;
        },
        c.trial, 1e-7);
    EXPECT_LT(test::relative_error(df_dx, fd), 1e-6) << c.name;
  }
}

TEST(HistoryTimeStepping, SteppingFromThePeriodicHistoryReproducesThePeriodicForces) {
  // history_step from the variables after sample t-1 to sample t is the return mapping the
  // periodic pass makes (over the sample interval, which the turning casing needs): forces and
  // variables agree to round-off, in stick, slip and separation.
  const ElementList elements = history_elements();
  const int n = 128;
  MatrixXd x(n, 3);
  for (int t = 0; t < n; ++t) {
    const double th = 2 * std::numbers::pi * t / n;
    x(t, 0) = 0.3 * std::cos(th) + 0.05 * std::sin(3 * th);
    x(t, 1) = 0.2 * std::sin(th + 0.3) - 0.1 * std::cos(2 * th);
    x(t, 2) = 0.3 * std::cos(th + 1.0);  // separates when 5 x3 < -1
  }
  for (const auto& e : elements) {
    MatrixXd local(n, e->local_dofs());
    for (int i = 0; i < e->local_dofs(); ++i) local.col(i) = x.col(e->dofs[static_cast<size_t>(i)]);
    const std::vector<double> props = e->property_values(ParameterSet());
    ElementResponse r;
    e->evaluate(local, local, 1.0, props, r, false);
    const MatrixXd history = e->periodic_history(local, 1.0, props);
    ASSERT_EQ(history.cols(), e->history_state_size()) << e->type();
    HistoryStep step;
    for (int t = 0; t < n; ++t) {
      e->history_step(local.row(t), history.row((t + n - 1) % n).transpose(), 2 * std::numbers::pi / n, 1.0, props, step);
      EXPECT_LT((step.force.transpose() - r.force.row(t)).cwiseAbs().maxCoeff(), 1e-12) << e->type() << " sample " << t;
      EXPECT_LT((step.state - history.row(t).transpose()).cwiseAbs().maxCoeff(), 1e-12) << e->type() << " sample " << t;
    }
  }
}

TEST(HistoryTimeStepping, ThreeOscillatorsStayOnTheHbmOrbit) {
  // NLvib's chain (examples/three_oscillators_jenkins.toml): two Jenkins elements, two cubic
  // springs and a unilateral spring. Started on an HBM orbit with the sliders at its periodic
  // state, Newmark (1024 steps per period, O((2 pi / 1024)^2) ~ 4e-5 of the amplitude) settles
  // on the periodic motion nearest it. The force has kinks, so the orbit's harmonics decay
  // slowly: measured against H = 41, the truncation error at omega = 0.8 is 1.7e-2 of the range
  // at H = 7 (the example's) and 3e-5 at H = 21; at omega = 1.6, 1.3e-4 and 4e-6. So at H = 21
  // the simulation must stay within 2e-4 of the range of the orbit, and at H = 7 it must show
  // the example's truncation error (more than 3 times the H = 21 deviation at omega = 0.8).
  // Seven minutes under the sanitizers (Newmark to the steady state at 1024 steps per period):
  // the Release pass checks these numbers; MonodromyMultipliersMatchTheTimeIntegratorsFlow runs
  // Newmark with sliders under the sanitizers.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers: run by the Release pass";
  for (double omega : {0.8, 1.6}) {
    double deviation[2] = {0, 0};
    for (int h : {21, 7}) {
      if (h == 7 && omega != 0.8) continue;
      CaseDefinition c = load_case(test::source_path("examples/three_oscillators_jenkins.toml"),
                                   {"harmonic_balance.harmonics=" + std::to_string(h), "harmonic_balance.samples=2048"});
      HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
      const int n = c.model.dofs();
      const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-10, 100);
      ASSERT_TRUE(s.converged) << "omega " << omega;
      const VectorXd full = hbm.expand(s.x, omega);
      EquationOfMotion eom(c.model, c.elements, hbm.parameters(), omega);
      MotionState start = state_from_harmonics(full, n, h, omega);
      start.history = eom.periodic_history(period_samples(full, n, h, hbm.basis().samples()));
      NewmarkOptions options;
      options.steps_per_period = 1024;
      NewmarkIntegrator integrator(eom, options);
      SteadyStateOptions steady;
      steady.harmonics = h;
      const SteadyStateResult r = integrate_to_steady_state(integrator, start, c.outputs, steady);
      ASSERT_TRUE(r.converged) << "omega " << omega << ": " << r.stop_reason;
      // The simulated last period against the HBM orbit at the same instants.
      double worst = 0;
      const MatrixXd orbit = period_samples(full, n, h, options.steps_per_period);
      for (size_t o = 0; o < c.outputs.size(); ++o) {
        const VectorXd expected = orbit.col(c.outputs[o].dof);
        const double range = expected.maxCoeff() - expected.minCoeff();
        worst = std::max(worst, (r.signals.col(static_cast<Eigen::Index>(o)) - expected).cwiseAbs().maxCoeff() / range);
      }
      deviation[h == 7] = worst;
      std::printf("[ measured ] omega %.2f, H = %d: periodic after %d periods, largest deviation from the HBM orbit %.2e of the range\n",
                  omega, h, r.periods, worst);
    }
    EXPECT_LT(deviation[0], 2e-4) << "omega " << omega;
    if (omega == 0.8) {
      EXPECT_GT(deviation[1], 3 * deviation[0]) << "the H = 7 truncation error should show";
    }
  }
}

namespace {

// A unit oscillator (damping 0.02) with a Jenkins element (stiffness 1, slip force 0.1),
// forced by 0.1 cos(omega t); H = 21 so that the orbit's truncation error (1e-5) stays below
// what the multipliers are compared to.
HarmonicBalance jenkins_oscillator() {
  StructuralModel m;
  m.dof_names = {"x"};
  m.mass = MatrixXd::Identity(1, 1);
  m.stiffness = MatrixXd::Identity(1, 1);
  m.damping = 0.02 * m.stiffness;
  m.forcing.push_back({1, VectorXd::Constant(1, 0.1), VectorXd::Zero(1)});
  auto e = std::make_shared<ElasticDryFriction>();
  e->weights = VectorXd::Ones(1);
  return HarmonicBalance(m, {with_properties(e, {0}, {1.0, 0.1})}, ParameterSet(),
                         HarmonicBalanceOptions{21, 4096, Condensation::none, {}, 1, {}});
}

// Multipliers of the time integrator's own map over one period, by central differences of
// (x, v, z) -> (x, v, z)(T) started on the orbit (Newmark, trapezoidal rule, `steps` steps).
Eigen::VectorXcd flow_multipliers(HarmonicBalance& hbm, const VectorXd& x, double omega, int steps) {
  const int h = hbm.basis().harmonics();
  const VectorXd full = hbm.expand(x, omega);
  EquationOfMotion eom(hbm.model(), hbm.elements(), hbm.parameters(), omega);
  MotionState start = state_from_harmonics(full, 1, h, omega);
  start.history = eom.periodic_history(period_samples(full, 1, h, hbm.basis().samples()));
  NewmarkOptions options;
  options.steps_per_period = steps;
  options.alpha = 0.0;
  NewmarkIntegrator integrator(eom, options);
  const auto flow = [&](const VectorXd& y) {
    MotionState s = start;
    s.x(0) = y(0), s.v(0) = y(1), s.history(0) = y(2);
    integrator.start(s);
    integrator.advance_period(nullptr);
    const MotionState& end = integrator.state();
    return VectorXd((VectorXd(3) << end.x(0), end.v(0), end.history(0)).finished());
  };
  const VectorXd y0 = (VectorXd(3) << start.x(0), start.v(0), start.history(0)).finished();
  return Eigen::EigenSolver<MatrixXd>(test::fd_jacobian(flow, y0, 1e-7)).eigenvalues();
}

}  // namespace

TEST(HistoryTimeStepping, MonodromyMultipliersMatchTheTimeIntegratorsFlow) {
  HarmonicBalance hbm = jenkins_oscillator();
  // omega = 0.9: the slider sticks all period (amplitude 0.084 < F/k = 0.1); the motion is the
  // linear oscillator of stiffness 2, multipliers exp((-0.01 +- i sqrt(2 - 1e-4)) T), which RK4
  // with 4000 steps reproduces to (omega_n dt)^4 ~ 1e-10.
  {
    const double omega = 0.9, period = 2 * std::numbers::pi / omega;
    const FixedFrequencySolution s = solve_at_frequency(hbm, omega, {{"x", 0, ""}}, 1e-11, 50);
    ASSERT_TRUE(s.converged);
    ASSERT_LT(s.recorded.outputs[0].max, 0.1);
    const FloquetResult r = monodromy_floquet(hbm, s.x, omega, 4000);
    ASSERT_EQ(r.multipliers.size(), 2);
    const std::complex<double> exact = std::exp(std::complex<double>(-0.01, std::sqrt(2 - 1e-4)) * period);
    for (int i = 0; i < 2; ++i)
      EXPECT_LT(std::min(std::abs(r.multipliers(i) - exact), std::abs(r.multipliers(i) - std::conj(exact))), 1e-8);
  }
  // Stick-slip: the variational equation against the integrator's own flow. Both place the
  // stick-slip transitions on their step grids, an O(dt) error (2 pi / 8000 ~ 8e-4 of the
  // multipliers); measured 4e-5 and 2.4e-4. Hill's multipliers, from the periodic (lambda = 0)
  // linearisation of the hysteresis, are printed for docs/stability.md.
  for (double omega : {1.1, 1.3}) {
    const FixedFrequencySolution s = solve_at_frequency(hbm, omega, {{"x", 0, ""}}, 1e-11, 50);
    ASSERT_TRUE(s.converged) << "omega " << omega;
    const FloquetResult r = monodromy_floquet(hbm, s.x, omega, 8000);
    const Eigen::VectorXcd flow = flow_multipliers(hbm, s.x, omega, 8192);
    ASSERT_EQ(r.multipliers.size(), 2);
    for (int i = 0; i < 2; ++i) {
      double nearest = INFINITY;
      for (int j = 0; j < 3; ++j) nearest = std::min(nearest, std::abs(r.multipliers(i) - flow(j)));
      EXPECT_LT(nearest, 1e-3) << "omega " << omega << " multiplier " << r.multipliers(i);
    }
    const FloquetResult hill = hill_floquet(hbm, s.x, omega, HillSolver::dense);
    std::printf("[ measured ] omega %.1f: largest Floquet exponent real part: monodromy %.4f, Hill %.4f\n", omega, r.max_real,
                hill.max_real);
  }
}

TEST(HistoryTimeStepping, ThreeOscillatorsMonodromyVerdictsAreTheSimulations) {
  // Along NLvib's three-oscillator NFRC Hill's and the monodromy's verdicts differ at 48 of 273
  // points (docs/stability.md). At two of them the time integration decides: near omega = 1.25
  // (first resonance) the monodromy says stable and a simulation started on the orbit stays
  // there (within the H = 7 truncation error, ~1e-3 of the amplitude); near omega = 1.64, on
  // the upper branch after the first fold, it says unstable and the simulation leaves for
  // another orbit (x3's largest value drops from 0.78 to 0.16, a third of its range).
  // Two and a half minutes under the sanitizers (the NFRC and two simulations to the steady
  // state): the Release pass checks these verdicts; MonodromyMultipliersMatchTheTimeIntegratorsFlow
  // runs the monodromy matrix and Newmark with sliders under the sanitizers.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers: run by the Release pass";
  CaseDefinition c = load_case(test::source_path("examples/three_oscillators_jenkins.toml"));
  c.nfrc.stability.method = StabilityMethod::none;
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult nfrc = compute_nfrc(hbm, c.nfrc, c.outputs);
  const auto& points = nfrc.continuation.points;
  ASSERT_EQ(nfrc.continuation.summary.stop_reason, StopReason::reached_end);
  // The first point past omega = 1.25, and the first past 1.635 after the branch has folded back
  // below 1.628 (the fold at 1.628 is a cluster of sampled-law LPs).
  size_t stays = 0, leaves = 0;
  while (points[stays].lambda < 1.25) ++stays;
  size_t folded = 0;
  while (!(points[folded].lambda > 1.62 && points[folded + 1].lambda < points[folded].lambda)) ++folded;
  for (leaves = folded; points[leaves].lambda < 1.635; ++leaves) ASSERT_LT(leaves + 1, points.size());
  const int n = c.model.dofs(), h = c.harmonic_balance.harmonics;
  for (const size_t index : {stays, leaves}) {
    const BranchPoint& p = points[index];
    const FloquetResult monodromy = monodromy_floquet(hbm, p.u, p.lambda, 2000);
    const FloquetResult hill = hill_floquet(hbm, p.u, p.lambda, HillSolver::automatic);
    const VectorXd full = hbm.expand(p.u, p.lambda);
    EquationOfMotion eom(c.model, c.elements, hbm.parameters(), p.lambda);
    MotionState start = state_from_harmonics(full, n, h, p.lambda);
    start.history = eom.periodic_history(period_samples(full, n, h, hbm.basis().samples()));
    NewmarkIntegrator integrator(eom, NewmarkOptions{});
    SteadyStateOptions steady;
    steady.harmonics = h;
    steady.max_periods = 600;
    const SteadyStateResult r = integrate_to_steady_state(integrator, start, c.outputs, steady);
    ASSERT_TRUE(r.converged) << "omega " << p.lambda << ": " << r.stop_reason;
    const VectorXd x3 = period_samples(full, n, h, 64).col(2);
    const double change = std::abs(r.outputs[2].max - x3.maxCoeff()) / (x3.maxCoeff() - x3.minCoeff());
    std::printf("[ measured ] omega %.4f: monodromy %s (%.4f), Hill %s (%.4f); simulated x3 extreme moved by %.2e of its range\n", p.lambda,
                monodromy.stable ? "stable" : "unstable", monodromy.max_real, hill.stable ? "stable" : "unstable", hill.max_real, change);
    if (index == stays) {
      EXPECT_TRUE(monodromy.stable);
      EXPECT_LT(change, 1e-2);
    } else {
      EXPECT_FALSE(monodromy.stable);
      EXPECT_GT(change, 0.2);
    }
  }
}

}  // namespace hbtrack_tests::file_history_time_stepping
