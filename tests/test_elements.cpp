// Every element's analytic derivatives against central finite differences, pointwise in time,
// in each regime of the contact laws (open, blending, closed).
#include <gtest/gtest.h>

#include "hbtrack/elements/contact_laws.hpp"
#include "hbtrack/elements/lanczos.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_elements {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Finite-difference check of one element at samples x, v. h is small relative to the data
// (O(1)), and central differences leave an O(h^2) error: 1e-6 relative is far above it.
void check_element(const NonlinearElement& e, const MatrixXd& x, const MatrixXd& v, double omega, std::vector<double> props) {
  const int k = e.local_dofs();
  const double h = 1e-6, tol = 1e-6;
  ElementResponse r;
  e.evaluate(x, v, omega, props, r, true);
  auto force = [&](const MatrixXd& xx, const MatrixXd& vv, double w, const std::vector<double>& p) {
    ElementResponse out;
    e.evaluate(xx, vv, w, p, out, false);
    return out.force;
  };
  for (int j = 0; j < k; ++j) {
    MatrixXd xp = x, xm = x;
    xp.col(j).array() += h;
    xm.col(j).array() -= h;
    const MatrixXd fd = (force(xp, v, omega, props) - force(xm, v, omega, props)) / (2 * h);
    for (int i = 0; i < k; ++i)
      EXPECT_LT((fd.col(i) - r.dforce_dx.col(i + k * j)).cwiseAbs().maxCoeff(), tol * std::max(1.0, fd.col(i).cwiseAbs().maxCoeff()))
          << e.type() << " df" << i << "/dx" << j;
    if (e.depends_on_velocity()) {
      MatrixXd vp = v, vm = v;
      vp.col(j).array() += h;
      vm.col(j).array() -= h;
      const MatrixXd fdv = (force(x, vp, omega, props) - force(x, vm, omega, props)) / (2 * h);
      for (int i = 0; i < k; ++i)
        EXPECT_LT((fdv.col(i) - r.dforce_dv.col(i + k * j)).cwiseAbs().maxCoeff(), tol * std::max(1.0, fdv.col(i).cwiseAbs().maxCoeff()))
            << e.type() << " df" << i << "/dv" << j;
    }
  }
  if (e.depends_on_omega()) {
    const MatrixXd fdw = (force(x, v, omega + h, props) - force(x, v, omega - h, props)) / (2 * h);
    EXPECT_LT((fdw - r.dforce_domega).cwiseAbs().maxCoeff(), tol * std::max(1.0, fdw.cwiseAbs().maxCoeff())) << e.type() << " df/domega";
  }
  for (size_t p = 0; p < props.size(); ++p) {
    auto pp = props, pm = props;
    const double hp = h * std::max(1.0, std::abs(props[p]));
    pp[p] += hp;
    pm[p] -= hp;
    const MatrixXd fdp = (force(x, v, omega, pp) - force(x, v, omega, pm)) / (2 * hp);
    EXPECT_LT((fdp - r.dforce_dproperty.middleCols(static_cast<Eigen::Index>(k * p), k)).cwiseAbs().maxCoeff(),
              tol * std::max(1.0, fdp.cwiseAbs().maxCoeff()))
        << e.type() << " df/d" << e.property_names()[p];
  }
}

MatrixXd samples(int n, int k, double lo, double hi, unsigned seed) {
  std::srand(seed);
  return (MatrixXd::Random(n, k).array() + 1.0) * 0.5 * (hi - lo) + lo;
}

}  // namespace

TEST(ContactLaws, DerivativesInEveryRegime) {
  for (ContactLawKind kind : {ContactLawKind::penalty, ContactLawKind::polynomial, ContactLawKind::sqrt}) {
    // Avoid the kinks of the C0 penalty law (g = 0) and of the polynomial blend (k g = +-width).
    for (double g : {-0.3, -0.05, 0.02, 0.07, 0.4}) {
      const double k = 3.0, w = 0.2, h = 1e-7;
      const ContactForce c = contact_force(kind, g, k, w);
      EXPECT_NEAR(c.d_gap, (contact_force(kind, g + h, k, w).force - contact_force(kind, g - h, k, w).force) / (2 * h), 1e-6);
      EXPECT_NEAR(c.d_stiffness, (contact_force(kind, g, k + h, w).force - contact_force(kind, g, k - h, w).force) / (2 * h), 1e-6);
      EXPECT_NEAR(c.d_width, (contact_force(kind, g, k, w + h).force - contact_force(kind, g, k, w - h).force) / (2 * h), 1e-6);
    }
  }
}

TEST(ContactLaws, PolynomialIsC1AndExactOutsideTheBlend) {
  const double k = 10.0, w = 0.5;
  EXPECT_EQ(contact_force(ContactLawKind::polynomial, -0.06, k, w).force, 0.0);
  EXPECT_DOUBLE_EQ(contact_force(ContactLawKind::polynomial, 0.2, k, w).force, 2.0);
  for (double s : {-w, w}) {  // value and slope continuous at both ends of the blend
    const double g = s / k, e = 1e-12;
    EXPECT_NEAR(contact_force(ContactLawKind::polynomial, g - e, k, w).force, contact_force(ContactLawKind::polynomial, g + e, k, w).force,
                1e-9);
    EXPECT_NEAR(contact_force(ContactLawKind::polynomial, g - e, k, w).d_gap, contact_force(ContactLawKind::polynomial, g + e, k, w).d_gap,
                1e-6);
  }
}

TEST(Elements, CubicSpringBetweenTwoDofs) {
  CubicSpring e;
  e.dofs = {0, 1};
  e.weights = (VectorXd(2) << 1.0, -1.0).finished();
  check_element(e, samples(40, 2, -1.5, 1.5, 1), samples(40, 2, -1, 1, 2), 1.0, {0.7});
}

TEST(Elements, UnilateralAndRegularizedContact) {
  for (ContactLawKind kind : {ContactLawKind::penalty, ContactLawKind::polynomial, ContactLawKind::sqrt}) {
    GapContact e(kind, "regularized_contact");
    e.dofs = {0};
    e.weights = VectorXd::Ones(1);
    check_element(e, samples(50, 1, -0.5, 0.9, 3), samples(50, 1, -1, 1, 4), 1.0, {5.0, 0.13, 0.4});
  }
}

TEST(Elements, TanhFriction) {
  TanhFriction e;
  e.dofs = {0, 1};
  e.weights = (VectorXd(2) << 1.0, -0.5).finished();
  check_element(e, samples(40, 2, -1, 1, 5), samples(40, 2, -0.3, 0.3, 6), 1.0, {0.3, 2.0, 0.05});
}

TEST(Elements, TipContactNormalAndFrictionForces) {
  for (ContactLawKind kind : {ContactLawKind::polynomial, ContactLawKind::sqrt}) {
    TipContact e(kind);
    e.dofs = {0, 1, 2};
    // Radial displacement straddles the clearance; sliding speeds of either sign.
    check_element(e, samples(60, 3, -0.2, 0.5, 7), samples(60, 3, -2.0, 2.0, 8), 1.7, {40.0, 0.1, 0.5, 0.15, 0.8, 1.0, 0.3});
  }
}

TEST(Elements, TipContactFrictionOpposesSliding) {
  TipContact e(ContactLawKind::penalty);
  e.dofs = {0, 1, 2};
  MatrixXd x(1, 3), v(1, 3);
  x << 0.3, 0.0, 0.0;
  v << 0.0, 0.0, 0.0;
  ElementResponse r;
  // Tip speed rho W = 0.5 * 100 along +theta: f_theta = mu f_N, no axial force, f_N = k g.
  e.evaluate(x, v, 100.0, {10.0, 0.1, 0.0, 0.2, 0.5, 1.0, 0.0}, r, false);
  EXPECT_DOUBLE_EQ(r.force(0, 0), 2.0);
  EXPECT_DOUBLE_EQ(r.force(0, 1), 0.4);
  EXPECT_DOUBLE_EQ(r.force(0, 2), 0.0);
}

TEST(Lanczos, SigmaFactors) {
  const VectorXd s = lanczos_factors(4, 1.0);
  EXPECT_DOUBLE_EQ(s(0), 1.0);
  EXPECT_NEAR(s(1), std::sin(M_PI / 5) / (M_PI / 5), 1e-15);
  EXPECT_EQ(s(1), s(2));
  EXPECT_GT(s(1), s(7));
  EXPECT_TRUE(lanczos_factors(4, 0.0).isOnes());
}

}  // namespace hbtrack_tests::file_elements
