// The assembled harmonic balance residual: analytic Jacobian, d/d(omega) and d/d(parameter)
// against finite differences, with and without condensation and Lanczos filtering; the
// time-domain product J_nl^T w against the assembled Jacobian; condensed and full systems agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/hbm/recorded_outputs.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_harmonic_balance {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

struct Variant {
  bool general_damping;
  const char* condensation;
  double lanczos;
};

// A state whose tip node enters contact over part of the period (radial amplitude > clearance).
VectorXd contact_state(HarmonicBalance& hbm) {
  std::srand(11);
  VectorXd x = 0.01 * VectorXd::Random(hbm.unknowns());
  const int q = hbm.retained_dofs();
  x(1 * q + 0) = 0.08;  // a1 of the radial dof
  x(2 * q + 1) = 0.05;  // b1 of the circumferential dof
  return x;
}

// Finite-difference steps: unknowns are O(0.1), so h = 1e-7 leaves truncation ~1e-14 and
// round-off ~1e-9 relative; 1e-6 is a safe bound that an error in any term would exceed.
constexpr double kStep = 1e-7;
constexpr double kTolerance = 1e-6;

// The contact fixture of a variant, at H = 4 and N = 64.
HarmonicBalance variant_model(const Variant& v) {
  test::ContactFixture f = test::contact_fixture(v.general_damping, v.lanczos);
  HarmonicBalanceOptions o;
  o.harmonics = 4;
  o.samples = 64;
  o.condensation = parse_condensation(v.condensation);
  return HarmonicBalance(f.model, f.elements, f.parameters, o);
}

class HarmonicBalanceDerivatives : public ::testing::TestWithParam<Variant> {};

TEST_P(HarmonicBalanceDerivatives, MatchFiniteDifferences) {
  HarmonicBalance hbm = variant_model(GetParam());
  const double omega = 1.3;
  const VectorXd x = contact_state(hbm);

  VectorXd r, r_omega;
  MatrixXd jac;
  hbm.evaluate(x, omega, r, &jac, &r_omega);
  auto residual = [&](const VectorXd& xx) {
    VectorXd rr;
    hbm.evaluate(xx, omega, rr);
    return rr;
  };
  EXPECT_LT(test::relative_error(jac, test::fd_jacobian(residual, x, kStep)), kTolerance) << "dR/dx";

  auto at_omega = [&](double w) {
    VectorXd rr;
    hbm.evaluate(x, w, rr);
    return rr;
  };
  EXPECT_LT(test::relative_error(r_omega, test::central_difference(at_omega, omega, kStep)), kTolerance) << "dR/domega";

  for (const std::string name : {"amplitude", "mu", "clearance"}) {
    const int p = hbm.parameters().find(name);
    const double p0 = hbm.parameters().value(p);
    const VectorXd analytic = hbm.parameter_derivative(x, omega, p);
    auto at_p = [&](double value) {
      hbm.set_parameter(p, value);
      VectorXd rr;
      hbm.evaluate(x, omega, rr);
      return rr;
    };
    const VectorXd fd = test::central_difference(at_p, p0, kStep * std::max(1.0, p0));
    hbm.set_parameter(p, p0);
    EXPECT_GT(fd.cwiseAbs().maxCoeff(), 1e-6) << "the state must make dR/d" << name << " non-trivial";
    EXPECT_LT(test::relative_error(analytic, fd), kTolerance) << "dR/d" << name;
  }
}

// The condensed linear part Zr(omega) column by column: with the forcing off, R - f_nl = Zr x
// exactly (to round-off), whatever x. Columns at a small x keep the contact open.
MatrixXd condensed_linear_jacobian(HarmonicBalance& hbm, double omega) {
  const double saved = hbm.parameters().value(hbm.amplitude_parameter());
  hbm.set_parameter(hbm.amplitude_parameter(), 0.0);
  const double scale = 1e-3;
  MatrixXd zr(hbm.unknowns(), hbm.unknowns());
  for (int c = 0; c < hbm.unknowns(); ++c) {
    const VectorXd x = scale * VectorXd::Unit(hbm.unknowns(), c);
    VectorXd r;
    hbm.evaluate(x, omega, r);
    zr.col(c) = (r - hbm.nonlinear_forces(x, omega)) / scale;
  }
  hbm.set_parameter(hbm.amplitude_parameter(), saved);
  return zr;
}

TEST_P(HarmonicBalanceDerivatives, NonlinearAdjointProductsMatchTheAssembledDerivatives) {
  HarmonicBalance hbm = variant_model(GetParam());
  const double omega = 1.3;
  const VectorXd x = contact_state(hbm);
  VectorXd r;
  MatrixXd jac;
  hbm.evaluate(x, omega, r, &jac);
  const MatrixXd nonlinear = jac - condensed_linear_jacobian(hbm, omega);
  const VectorXd w = VectorXd::Random(hbm.unknowns());
  const VectorXd expected = nonlinear.transpose() * w;
  VectorXd product;
  const double w_dot_omega_derivative = hbm.nonlinear_adjoint_products(x, omega, w, product);
  // Both sides are the same sums in another order (product_matrix equals Gamma^-1 diag(g) Gamma
  // for any N), so they differ by round-off only: a few ulps of the largest entries, far below 1e-12.
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1.0) << "the contact state must make J_nl non-trivial";
  EXPECT_LT(test::relative_error(product, expected), 1e-12);
  // The velocity terms are checked too: the friction dof's entries come from them alone (its
  // element depends on velocity only and shares the dof with no other element).
  const int q = hbm.retained_dofs();
  const auto friction_dof = std::find(hbm.retained().begin(), hbm.retained().end(), 5) - hbm.retained().begin();
  double friction_part = 0.0;
  for (int c = 0; c < hbm.basis().coefficients(); ++c) friction_part = std::max(friction_part, std::abs(expected(c * q + friction_dof)));
  EXPECT_GT(friction_part, 1e-2 * expected.cwiseAbs().maxCoeff());

  // w . df_nl/d(omega): without forcing, R_omega less the linear part (dZr/d(omega)) x. Both
  // sides are sums of terms up to `scale` (mostly the linear part's), so they agree to round-off
  // of it; the nonlinear part must stand far above that tolerance.
  hbm.set_parameter(hbm.amplitude_parameter(), 0.0);
  VectorXd r_omega;
  hbm.evaluate(x, omega, r, nullptr, &r_omega);
  const VectorXd linear = hbm.linear_omega_derivative(x, omega);
  const double expected_omega = w.dot(r_omega - linear);
  const double scale = w.cwiseAbs().dot(r_omega.cwiseAbs() + linear.cwiseAbs());
  EXPECT_GT(std::abs(expected_omega), 1e-6 * scale) << "the velocity dependence must make df_nl/domega non-trivial";
  EXPECT_LT(std::abs(w_dot_omega_derivative - expected_omega), 1e-12 * scale);
}

INSTANTIATE_TEST_SUITE_P(AllVariants, HarmonicBalanceDerivatives,
                         ::testing::Values(Variant{false, "none", 0.0}, Variant{false, "none", 1.0}, Variant{false, "modal", 0.0},
                                           Variant{false, "modal", 1.0}, Variant{false, "schur", 1.0}, Variant{true, "schur", 0.0},
                                           Variant{true, "schur", 1.0}, Variant{true, "none", 2.0}));

TEST(HarmonicBalance, AutoCondensationPicksModalOnlyForProportionalDampingAndFewNonlinearDofs) {
  test::ContactFixture prop = test::contact_fixture(false, 0);
  test::ContactFixture gen = test::contact_fixture(true, 0);
  HarmonicBalanceOptions o;
  o.harmonics = 2;
  // Only the friction element: 1 nonlinear dof of 9.
  const ElementList friction_only{prop.elements.back()};
  EXPECT_EQ(HarmonicBalance(prop.model, friction_only, prop.parameters, o).condensation_method(), "modal");
  EXPECT_EQ(HarmonicBalance(gen.model, friction_only, gen.parameters, o).condensation_method(), "schur");
  // Every element: 6 nonlinear dofs of 9, too many for a well-conditioned receptance inverse.
  EXPECT_EQ(HarmonicBalance(prop.model, prop.elements, prop.parameters, o).condensation_method(), "schur");
  o.condensation = Condensation::modal;
  EXPECT_THROW(HarmonicBalance(gen.model, gen.elements, gen.parameters, o), std::invalid_argument);
}

TEST(HarmonicBalance, CondensedAndFullSystemsGiveTheSameSolution) {
  for (bool general : {false, true}) {
    test::ContactFixture f = test::contact_fixture(general, 1.0);
    const double omega = 1.3, tol = 1e-12;
    std::vector<VectorXd> full_solutions;
    for (const char* method : {"none", "schur", "modal"}) {
      if (general && std::string(method) == "modal") continue;
      HarmonicBalanceOptions o;
      o.harmonics = 5;
      o.samples = 128;
      o.condensation = parse_condensation(method);
      HarmonicBalance hbm(f.model, f.elements, f.parameters, o);
      NfrcProblem problem(hbm, 0.1, 1.0, 1.0);
      VectorXd x = hbm.linear_solution(omega);
      ASSERT_GE(newton_at_fixed_parameter(problem, x, omega, tol, 50), 0) << method;
      full_solutions.push_back(hbm.expand(x, omega));
    }
    for (size_t i = 1; i < full_solutions.size(); ++i)
      EXPECT_LT((full_solutions[i] - full_solutions[0]).cwiseAbs().maxCoeff(), 1e-10 * full_solutions[0].cwiseAbs().maxCoeff())
          << "general damping " << general << ", method " << i;
    // The solution really is in contact (otherwise this would only test the linear part).
    EXPECT_GT(dof_signal(full_solutions[0], 9, 5, 0, 512).maxCoeff(), f.parameters.value("clearance"));
  }
}

}  // namespace hbtrack_tests::file_harmonic_balance
