// The time-domain equation of motion (forcing, element forces and tangents assembled on the full
// model) and both integrators on the 9-dof fixture that has every element type: tip contact
// with friction, a cubic spring between two dofs, tanh friction, a non-diagonal mass.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_timeint_equation {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(TimeIntegrationEquation, ExternalForceFollowsTheHarmonicForcing) {
  StructuralModel m;
  m.dof_names = {"a", "b"};
  m.mass = MatrixXd::Identity(2, 2);
  m.damping = MatrixXd::Zero(2, 2);
  m.stiffness = MatrixXd::Identity(2, 2);
  m.forcing = {HarmonicForce{0, VectorXd::Constant(2, 0.5), VectorXd::Constant(2, 9.0)},  // static: sin ignored
               HarmonicForce{1, (VectorXd(2) << 1.0, 0.0).finished(), (VectorXd(2) << 0.0, 2.0).finished()},
               HarmonicForce{3, (VectorXd(2) << 0.0, 0.25).finished(), VectorXd::Zero(2)}};
  ParameterSet p;
  p.set("amplitude", 2.0);
  const double omega = 1.7, t = 0.9;
  EquationOfMotion eom(m, {}, p, omega);
  VectorXd f;
  eom.external_force(t, f);
  EXPECT_NEAR(f(0), 2.0 * (0.5 + std::cos(omega * t)), 1e-14);
  EXPECT_NEAR(f(1), 2.0 * (0.5 + 2.0 * std::sin(omega * t) + 0.25 * std::cos(3 * omega * t)), 1e-14);
  EXPECT_THROW(EquationOfMotion(m, {}, p, 0.0), std::invalid_argument);
}

TEST(TimeIntegrationEquation, TangentsMatchFiniteDifferences) {
  const test::ContactFixture f = test::contact_fixture(false, 0.0);
  EquationOfMotion eom(f.model, f.elements, f.parameters, 1.1);
  // A state with the tip node in contact and sliding, the cubic spring stretched and the
  // friction element near its regularisation velocity.
  VectorXd x(9), v(9);
  x << 0.05, -0.1, 0.2, 0.3, -0.2, 0.1, 0.0, 0.05, -0.05;
  v << 0.1, 0.4, -0.3, 0.2, 0.1, 0.03, 0.0, -0.1, 0.2;
  VectorXd force;
  MatrixXd df_dx, df_dv;
  eom.nonlinear_force(0.0, x, v, force, &df_dx, &df_dv);
  ASSERT_GT(force.cwiseAbs().maxCoeff(), 0.0);
  const auto force_at = [&](const VectorXd& xs, const VectorXd& vs) {
    VectorXd fs;
    eom.nonlinear_force(0.0, xs, vs, fs);
    return fs;
  };
  const MatrixXd fd_x = test::fd_jacobian([&](const VectorXd& xs) { return force_at(xs, v); }, x, 1e-6);
  const MatrixXd fd_v = test::fd_jacobian([&](const VectorXd& vs) { return force_at(x, vs); }, v, 1e-6);
  EXPECT_LT(test::relative_error(df_dx, fd_x), 1e-6);
  EXPECT_LT(test::relative_error(df_dv, fd_v), 1e-6);
  EXPECT_GT(df_dv.cwiseAbs().maxCoeff(), 0.0);
}

TEST(TimeIntegrationEquation, BothMethodsMatchTheHbmOnEveryElementType) {
  const test::ContactFixture f = test::contact_fixture(false, 0.0);
  const double omega = 1.0;
  const int harmonics = 20;  // friction and contact make the response rich in harmonics
  HarmonicBalanceOptions hb_options;
  hb_options.harmonics = harmonics;
  hb_options.samples = 1024;
  HarmonicBalance hbm(f.model, f.elements, f.parameters, hb_options);
  const std::vector<OutputDof> outputs{
      {"tip_radial", 0, ""}, {"tip_tangential", 1, ""}, {"cubic", 3, ""}, {"friction", 5, ""}, {"linear", 6, ""}};
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, outputs, 1e-10, 100);
  ASSERT_TRUE(s.converged);
  const MotionState start = state_from_harmonics(hbm.expand(s.x, omega), 9, harmonics, omega);

  EquationOfMotion eom(f.model, f.elements, f.parameters, omega);
  SteadyStateOptions options;
  options.harmonics = harmonics;
  std::vector<std::unique_ptr<TimeIntegrator>> integrators;
  integrators.push_back(std::make_unique<NewmarkIntegrator>(eom, NewmarkOptions{}));
  integrators.push_back(std::make_unique<DormandPrinceIntegrator>(eom, DormandPrinceOptions{}));
  for (const auto& integrator : integrators) {
    const SteadyStateResult r = integrate_to_steady_state(*integrator, start, outputs, options);
    ASSERT_TRUE(r.converged) << integrator->method() << ": " << r.stop_reason;
    double worst = 0;
    for (size_t i = 0; i < outputs.size(); ++i) {
      const OutputValues& e = s.recorded.outputs[i];
      const double range = e.max - e.min;
      worst = std::max({worst, std::abs(r.outputs[i].max - e.max) / range, std::abs(r.outputs[i].min - e.min) / range});
    }
    EXPECT_LT(worst, 0.01) << integrator->method();
    std::printf("[ measured ] %s: %d periods, %ld steps, worst extreme %.2e of range\n", integrator->method().c_str(), r.periods,
                r.statistics.steps, worst);
  }
}

}  // namespace hbtrack_tests::file_timeint_equation
