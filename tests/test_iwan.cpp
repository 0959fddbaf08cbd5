// The four-parameter Iwan element (Segalman 2005): its dissipation per cycle against the
// discrete array's closed form and against Segalman's continuous power law, the macro-slip force
// and stuck stiffness, and the exact AFT Jacobian against finite differences in micro- and
// macro-slip (its time-stepping form: test_history_time_stepping.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/elements/iwan.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_iwan {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// limit_force F_S, stiffness K_T, chi, beta
const std::vector<double> kProps{2.0, 50.0, -0.5, 0.4};

std::shared_ptr<Iwan> iwan(std::vector<int> dofs, VectorXd weights, int sliders = Iwan::kDefaultSliders) {
  auto e = std::make_shared<Iwan>(sliders);
  e->dofs = std::move(dofs);
  e->weights = std::move(weights);
  for (double p : kProps) e->properties.push_back(ParameterBinding::constant(p));
  return e;
}

VectorXd cosine(int n, double amplitude) {
  VectorXd d(n);
  for (int t = 0; t < n; ++t) d(t) = amplitude * std::cos(2 * std::numbers::pi * t / n);
  return d;
}

// Energy dissipated per cycle of d = a cos(theta): the loop area, -pi a s1 with s1 the sine
// coefficient of the force.
double dissipation(const Iwan& e, const std::vector<double>& props, double a, int n) {
  ElementResponse r;
  const VectorXd d = cosine(n, a);
  e.evaluate(d, d, 1.0, props, r, false);
  double s1 = 0;
  for (int t = 0; t < n; ++t) s1 += r.force(t, 0) * std::sin(2 * std::numbers::pi * t / n);
  return -std::numbers::pi * a * (2.0 / n) * s1;
}

// The discrete array's exact dissipation: a Jenkins slider of stiffness k and slip force F
// driven beyond its slip length phi = F/k dissipates 4 F (a - phi) per cycle.
double discrete_dissipation(const Iwan::SliderArray& s, double a) {
  double sum = 0;
  for (Eigen::Index i = 0; i < s.stiffness.size(); ++i) {
    if (s.stiffness(i) == 0) continue;
    const double phi = s.limit(i) / s.stiffness(i);
    if (a > phi) sum += 4 * s.limit(i) * (a - phi);
  }
  return sum;
}

// Segalman's continuous model in micro-slip (a < phi_max): D = 4 R a^(3+chi) / ((chi+2)(chi+3)).
double segalman_dissipation(const std::vector<double>& p, double phi_max, double a) {
  const double chi = p[2], beta = p[3];
  const double r = p[1] * (chi + 1) / ((1 + beta) * std::pow(phi_max, chi + 1));
  return 4 * r * std::pow(a, 3 + chi) / ((chi + 2) * (chi + 3));
}

}  // namespace

TEST(Iwan, StuckStiffnessAndMacroSlipForceAreExact) {
  const auto e = iwan({0}, VectorXd::Ones(1));
  const Iwan::SliderArray s = e->discretise(kProps);
  // The interval integrals make both sums exact whatever the grid.
  EXPECT_NEAR(s.stiffness.sum(), kProps[1], 1e-12 * kProps[1]);
  EXPECT_NEAR(s.limit.sum(), kProps[0], 1e-12 * kProps[0]);
  const double phi_max = s.phi_max;
  ElementResponse r;
  // Far beyond phi_max every slider slips: the force saturates at +-F_S.
  VectorXd d = cosine(256, 10 * phi_max);
  e->evaluate(d, d, 1.0, kProps, r, false);
  EXPECT_NEAR(r.force.maxCoeff(), kProps[0], 1e-12 * kProps[0]);
  EXPECT_NEAR(r.force.minCoeff(), -kProps[0], 1e-12 * kProps[0]);
  // Below the smallest slip length (1e-5 phi_max (chi+1)/(chi+2)) the joint is the stuck spring.
  d = cosine(256, 1e-7 * phi_max);
  e->evaluate(d, d, 1.0, kProps, r, false);
  EXPECT_LT((r.force.col(0) - kProps[1] * d).cwiseAbs().maxCoeff(), 1e-12 * kProps[1] * d.maxCoeff());
}

TEST(Iwan, DissipationMatchesTheDiscreteArrayExactly) {
  // Samples at the extremes of d and a monotone d between them make each force sample exact;
  // the loop area is then an N-point quadrature of a force with kinks, O((2 pi / N)^2) ~ 1.5e-7
  // relative at N = 2^14. 1e-6 bounds it.
  const auto e = iwan({0}, VectorXd::Ones(1));
  const Iwan::SliderArray s = e->discretise(kProps);
  for (double a : {1e-3, 1e-2, 0.1, 0.5, 0.99, 3.0}) {
    const double amplitude = a * s.phi_max;
    const double expected = discrete_dissipation(s, amplitude);
    EXPECT_NEAR(dissipation(*e, kProps, amplitude, 1 << 14), expected, 1e-6 * expected) << "a / phi_max = " << a;
  }
}

TEST(Iwan, MicroSlipDissipationFollowsSegalmansPowerLaw) {
  // The discrete array over-dissipates by the within-interval variance of phi and by the
  // interval that a cuts: both second order in the grid ratio 10^(-5/(n-1)). The study in
  // docs/elements.md measured a largest relative error of 3.15 (5/n)^2 over a in
  // [1e-3, 0.95] phi_max and chi in [-0.9, 0]; 4 (5/n)^2 bounds it. The bound and its
  // second-order decay are checked at n = 50 (the default) and 200.
  for (double chi : {-0.9, -0.5, 0.0}) {
    const std::vector<double> props{kProps[0], kProps[1], chi, kProps[3]};
    for (int sliders : {50, 200}) {
      const Iwan element(sliders);
      const Iwan::SliderArray s = element.discretise(props);
      const double bound = 4.0 * std::pow(Iwan::kDecades / sliders, 2);
      for (double a = 1e-3; a < 0.95; a *= 1.7) {
        const double amplitude = a * s.phi_max;
        const double exact = segalman_dissipation(props, s.phi_max, amplitude);
        EXPECT_NEAR(discrete_dissipation(s, amplitude) / exact, 1.0, bound) << "chi " << chi << " sliders " << sliders << " a " << a;
      }
    }
    // The power law itself, D ~ a^(3 + chi), from the element's own loops a decade apart.
    Iwan element;
    element.weights = VectorXd::Ones(1);
    const double phi_max = element.discretise(props).phi_max;
    const double slope =
        std::log10(dissipation(element, props, 0.05 * phi_max, 1 << 14) / dissipation(element, props, 0.005 * phi_max, 1 << 14));
    EXPECT_NEAR(slope, 3 + chi, 0.03) << "chi " << chi;  // log10(1 + 2 x 3.15 (5/50)^2) < 0.03
  }
}

TEST(Iwan, PropertyDerivativesMatchFiniteDifferences) {
  // Force samples are affine in each slider's (k, F) at a fixed stick-slip pattern and smooth in
  // the properties through them: central differences with h = 1e-6 relative have an O(h^2)
  // truncation error, far below 1e-6.
  const auto e = iwan({0, 1}, Eigen::Vector2d(1.0, -1.0));
  const double phi_max = e->discretise(kProps).phi_max;
  const int n = 96;
  for (double a : {0.05, 0.6, 4.0}) {  // micro-slip, deep micro-slip, macro-slip
    MatrixXd x(n, 2);
    for (int t = 0; t < n; ++t) {
      const double th = 2 * std::numbers::pi * t / n;
      x(t, 0) = a * phi_max * (std::cos(th) + 0.2 * std::sin(2 * th));
      x(t, 1) = 0.3 * a * phi_max * std::sin(th + 0.4);
    }
    for (double beta : {kProps[3], 0.0}) {
      std::vector<double> props = kProps;
      props[3] = beta;
      ElementResponse r;
      e->evaluate(x, x, 1.0, props, r, true);
      for (int p = 0; p < 4; ++p) {
        if (p == 3 && beta == 0.0) continue;  // beta >= 0: one-sided there
        const double h = 1e-6 * std::max(1.0, std::abs(props[static_cast<size_t>(p)]));
        const MatrixXd fd = test::property_difference(*e, x, x, props, static_cast<size_t>(p), h);
        EXPECT_LT((fd - r.dforce_dproperty.middleCols(2 * p, 2)).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, fd.cwiseAbs().maxCoeff()))
            << "a " << a << " beta " << beta << " property " << e->property_names()[static_cast<size_t>(p)];
      }
    }
  }
}

TEST(Iwan, AftJacobianMatchesFiniteDifferencesInMicroAndMacroSlip) {
  // Two masses between walls, an Iwan joint between them. At a fixed stick-slip pattern the residual is
  // affine in x: central differences are exact up to round-off / h (~1e-9 relative); a pattern
  // change within +-h needs a trial force within k_i h of a slip force, which these motions avoid.
  const StructuralModel m = test::chain_between_walls(2, 1);
  const auto e = iwan({1, 0}, Eigen::Vector2d(1.0, -1.0));
  const double phi_max = e->discretise(kProps).phi_max;
  HarmonicBalanceOptions options;
  options.harmonics = 3;
  options.samples = 64;
  options.condensation = Condensation::none;
  HarmonicBalance hbm(m, ElementList{e}, ParameterSet(), options);
  for (double a : {0.3, 5.0}) {  // micro-slip, macro-slip
    VectorXd x = VectorXd::Zero(hbm.unknowns());
    for (int c = 1; c < 7; ++c) {
      x(2 * c) = a * phi_max / (c * c) * std::cos(1.3 * c + 0.2);
      x(2 * c + 1) = -a * phi_max / (c * c) * std::sin(0.7 * c + 1.1);
    }
    EXPECT_LT(test::residual_jacobian_error(hbm, x, 0.9, 1e-7 * phi_max), 1e-6) << "a / phi_max = " << a;
  }
}

}  // namespace hbtrack_tests::file_iwan
