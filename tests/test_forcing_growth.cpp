// A forcing that grows with the frequency, amplitude (omega / omega_ref)^k f: its derivatives in
// omega and in the amplitude against finite differences (condensed and full systems), the linear
// response against the closed-form FRF, and the unbalanced disc with Jenkins supports
// (examples/unbalanced_disc_jenkins.toml) against time integration of the full model.
#include <gtest/gtest.h>

#include <complex>
#include <cstdio>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "test_support.hpp"
#include "time_integration_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_forcing_growth {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(ForcingGrowth, FactorAndDerivative) {
  const ForcingGrowth fixed;
  EXPECT_EQ(fixed.factor(3.7), 1.0);  // exactly: a fixed forcing is left untouched
  EXPECT_EQ(fixed.derivative(3.7), 0.0);
  const ForcingGrowth unbalance{2.0, 1.5};
  EXPECT_DOUBLE_EQ(unbalance.factor(3.0), 4.0);
  for (const ForcingGrowth g : {ForcingGrowth{2.0, 1.5}, ForcingGrowth{1.0, 0.7}, ForcingGrowth{2.5, 2.0}}) {
    // Central difference, step 1e-6 at omega ~ 1: truncation 1e-12, round-off 1e-10 relative.
    const double h = 1e-6, omega = 1.3;
    const double fd = (g.factor(omega + h) - g.factor(omega - h)) / (2 * h);
    EXPECT_NEAR(g.derivative(omega), fd, 1e-8 * std::abs(fd)) << "k = " << g.exponent;
  }
}

TEST(ForcingGrowth, RefusesANegativeExponentOrReference) {
  StructuralModel m = test::contact_fixture(false, 0.0).model;
  m.forcing_growth = {-1.0, 1.0};
  EXPECT_THROW(m.validate(), std::invalid_argument);
  m.forcing_growth = {2.0, 0.0};
  EXPECT_THROW(m.validate(), std::invalid_argument);
}

// The contact fixture's derivatives with its forcing growing as omega^2 (and as omega^1.5), as
// test_harmonic_balance checks the fixed forcing's: unknowns O(0.1), step 1e-7, bound 1e-6.
TEST(ForcingGrowth, ResidualDerivativesInOmegaAndAmplitudeMatchFiniteDifferences) {
  for (const char* condensation : {"schur", "modal", "none"}) {
    for (const ForcingGrowth growth : {ForcingGrowth{2.0, 1.1}, ForcingGrowth{1.5, 0.8}}) {
      test::ContactFixture f = test::contact_fixture(false, 1.0);
      f.model.forcing_growth = growth;
      HarmonicBalanceOptions o;
      o.harmonics = 4;
      o.samples = 64;
      o.condensation = parse_condensation(condensation);
      HarmonicBalance hbm(f.model, f.elements, f.parameters, o);
      std::srand(11);
      const VectorXd x = 0.01 * VectorXd::Random(hbm.unknowns());
      const double omega = 1.3;
      VectorXd r, r_omega;
      hbm.evaluate(x, omega, r, nullptr, &r_omega);
      const std::string label = std::string(condensation) + ", k = " + std::to_string(growth.exponent);
      EXPECT_LT(test::relative_error(r_omega, test::omega_difference(hbm, x, omega, 1e-7)), 1e-6) << label;
      const int a = hbm.amplitude_parameter();
      const VectorXd fd = test::parameter_difference(hbm, x, omega, a, 1e-7);
      EXPECT_LT(test::relative_error(hbm.parameter_derivative(x, omega, a), fd), 1e-6) << label;
      // The growth must be there: the same derivative without it differs by far more.
      StructuralModel fixed = f.model;
      fixed.forcing_growth = ForcingGrowth{};
      HarmonicBalance fixed_hbm(fixed, f.elements, f.parameters, o);
      VectorXd r_fixed, r_omega_fixed;
      fixed_hbm.evaluate(x, omega, r_fixed, nullptr, &r_omega_fixed);
      EXPECT_GT(test::relative_error(r_omega, r_omega_fixed), 1e-2) << label;
    }
  }
}

TEST(ForcingGrowth, LinearResponseIsTheClosedFormFrfTimesTheGrowth) {
  // m x'' + c x' + k x = A (w / w_ref)^2 f cos(w t): x1 = A (w / w_ref)^2 f / (k - m w^2 + i c w).
  StructuralModel m;
  m.dof_names = {"x"};
  m.mass = MatrixXd::Constant(1, 1, 2.0);
  m.stiffness = MatrixXd::Constant(1, 1, 3.0);
  m.damping = MatrixXd::Constant(1, 1, 0.1);
  m.forcing.push_back({1, VectorXd::Constant(1, 0.4), VectorXd::Zero(1)});
  m.forcing_growth = {2.0, 1.2};
  ParameterSet p;
  p.set("amplitude", 1.5);
  HarmonicBalance hbm(m, {}, p, HarmonicBalanceOptions{3, 16, Condensation::none, {}, 1, {}});
  for (double omega : {0.5, 1.2, 1.3, 2.5}) {
    const std::complex<double> x1 = 1.5 * std::pow(omega / 1.2, 2) * 0.4 / std::complex<double>(3.0 - 2.0 * omega * omega, 0.1 * omega);
    const VectorXd x = hbm.linear_solution(omega);
    // Unknowns [a0, a1, b1, ...] with a1 - i b1 = x1: exact to round-off.
    EXPECT_NEAR(x(1), x1.real(), 1e-13 * std::abs(x1)) << omega;
    EXPECT_NEAR(x(2), -x1.imag(), 1e-13 * std::abs(x1)) << omega;
  }
}

// The HBM orbit at H harmonics sampled at `steps` instants of a period, and its solution.
struct Orbit {
  VectorXd x;
  MatrixXd samples;
};
Orbit hbm_orbit(HarmonicBalance& hbm, const CaseDefinition& c, double omega, int harmonics, int steps) {
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-11, 100);
  EXPECT_TRUE(s.converged) << "omega " << omega << ", H = " << harmonics;
  return {s.x, period_samples(hbm.expand(s.x, omega), c.model.dofs(), harmonics, steps)};
}

TEST(ForcingGrowth, UnbalancedDiscWithJenkinsSupportsMatchesTimeIntegration) {
  // The example's disc (two Jenkins supports, unbalance growing as omega^2) below the first
  // critical speed (supports stuck), between the two (x slipping) and above (both slipping).
  // The tolerance from the harmonic truncation: the Jenkins force has kinks, so its harmonics
  // decay as 1/j^2 and the orbit's as 1/j^4; the truncation error of H = 21 is measured here
  // against H = 41 (it is the HBM's part of the deviation), and Newmark at 1024 steps per
  // period adds O((2 pi / 1024)^2) = 4e-5 of the range (the integrator's part, bounded by 1e-4).
  // Minutes under the sanitizers: the Release pass runs it.
  if (test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers: run by the Release pass";
  constexpr int kSteps = 1024, kHarmonics = 21, kReference = 41;
  for (double omega : {0.8, 1.15, 1.4}) {
    MatrixXd orbit[2];
    VectorXd solution;
    CaseDefinition c;
    for (int i = 0; i < 2; ++i) {
      const int h = i == 0 ? kHarmonics : kReference;
      c = load_case(test::source_path("examples/unbalanced_disc_jenkins.toml"),
                    {"harmonic_balance.harmonics=" + std::to_string(h), "harmonic_balance.samples=2048"});
      HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
      const Orbit o = hbm_orbit(hbm, c, omega, h, kSteps);
      orbit[i] = o.samples;
      if (i == 0) solution = o.x;
    }
    double truncation = 0;
    for (const OutputDof& out : c.outputs) {
      const VectorXd a = orbit[0].col(out.dof), b = orbit[1].col(out.dof);
      truncation = std::max(truncation, (a - b).cwiseAbs().maxCoeff() / (b.maxCoeff() - b.minCoeff()));
    }
    c = load_case(test::source_path("examples/unbalanced_disc_jenkins.toml"),
                  {"harmonic_balance.harmonics=" + std::to_string(kHarmonics), "harmonic_balance.samples=2048"});
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    // The simulation's force, written out by hand: 0.02 (omega / 1)^2 on x at t = 0.
    VectorXd force;
    EquationOfMotion(c.model, c.elements, c.parameters, omega).external_force(0.0, force);
    EXPECT_NEAR(force(0), 0.02 * omega * omega, 1e-15);
    const double deviation = test::deviation_from_time_integration(c, hbm, solution, omega, kHarmonics, kSteps);
    std::printf("[ measured ] omega %.2f: H = 21 truncation %.2e, deviation from Newmark %.2e of the range\n", omega, truncation,
                deviation);
    EXPECT_LT(deviation, truncation + 1e-4) << "omega " << omega;
  }
}

}  // namespace hbtrack_tests::file_forcing_growth
