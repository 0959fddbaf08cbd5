// frictional_contact: a Jenkins slider whose limit follows a varying normal load, with
// separation. Periodic steady state against stepping the law over many periods, the constant-
// load case against elastic_dry_friction, and the AFT Jacobian against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/elements/elastic_dry_friction.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_frictional_contact {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// normal_stiffness, tangential_stiffness, mu, normal_preload
const std::vector<double> kProps{5.0, 20.0, 0.4, 1.0};

std::shared_ptr<FrictionalContact> contact(std::vector<int> dofs) {
  auto e = std::make_shared<FrictionalContact>();
  e->dofs = std::move(dofs);
  for (double p : kProps) e->properties.push_back(ParameterBinding::constant(p));
  return e;
}

// [x_n, x_t] over one period: normal amplitude an (separation when 5 an > 1), tangential at.
MatrixXd motion(int n, double an, double at) {
  MatrixXd x(n, 2);
  for (int t = 0; t < n; ++t) {
    const double th = 2 * std::numbers::pi * t / n;
    x(t, 0) = an * std::cos(th + 0.3) + 0.2 * an * std::sin(2 * th);
    x(t, 1) = at * std::cos(th) + 0.3 * at * std::sin(3 * th + 0.5);
  }
  return x;
}

// The law stepped from rest over many periods (the reference periodic state: its last period).
VectorXd stepped_tangential_force(const MatrixXd& x, int periods) {
  double z = 0.0;
  VectorXd force(x.rows());
  for (int p = 0; p < periods; ++p)
    for (Eigen::Index t = 0; t < x.rows(); ++t) {
      const double normal = std::max(0.0, kProps[3] + kProps[0] * x(t, 0));
      if (normal <= 0.0) {
        z = x(t, 1);
        force(t) = 0.0;
        continue;
      }
      const double limit = kProps[2] * normal, trial = kProps[1] * (x(t, 1) - z);
      if (trial > limit) z = x(t, 1) - limit / kProps[1];
      if (trial < -limit) z = x(t, 1) + limit / kProps[1];
      force(t) = kProps[1] * (x(t, 1) - z);
    }
  return force;
}

}  // namespace

TEST(FrictionalContact, PeriodicStateMatchesSteppingTheLawFromRest) {
  // Once the slider has slipped or separated the state forgets the start: the stepped law's
  // tenth period equals the element's state up to round-off.
  const auto e = contact({0, 1});
  struct Regime {
    const char* name;
    double an, at;
  };
  for (const Regime& r : {Regime{"slip, always in contact", 0.1, 0.2}, Regime{"separation", 0.4, 0.2},
                          Regime{"separation, small tangential motion", 0.4, 0.004}}) {
    const MatrixXd x = motion(256, r.an, r.at);
    ElementResponse out;
    e->evaluate(x, x, 1.0, kProps, out, false);
    EXPECT_LT((out.force.col(1) - stepped_tangential_force(x, 10)).cwiseAbs().maxCoeff(), 1e-12) << r.name;
  }
}

TEST(FrictionalContact, ConstantNormalLoadIsTheJenkinsElement) {
  // x_n = 0: N = preload, slip limit mu * preload.
  const auto e = contact({0, 1});
  ElasticDryFriction jenkins;
  jenkins.dofs = {1};
  jenkins.weights = VectorXd::Ones(1);
  for (double at : {0.01, 0.5}) {  // stick (range < 2 mu N / kt = 0.04), slip
    MatrixXd x = motion(128, 0.0, at);
    ElementResponse a, b;
    e->evaluate(x, x, 1.0, kProps, a, false);
    jenkins.evaluate(x.col(1), x.col(1), 1.0, {kProps[1], kProps[2] * kProps[3]}, b, false);
    EXPECT_LT((a.force.col(1) - b.force.col(0)).cwiseAbs().maxCoeff(), 1e-12) << "amplitude " << at;
  }
}

TEST(FrictionalContact, DerivativesMatchFiniteDifferences) {
  // Element level, all sample pairs: at a fixed pattern of stick, slip and separation the law
  // is affine in x (and in each property but mu), so central differences are exact up to
  // round-off / h (~1e-9 relative).
  const auto e = contact({0, 1});
  const int n = 96;
  for (double an : {0.1, 0.4}) {
    for (double at : {0.005, 0.2}) {
      const MatrixXd x = motion(n, an, at);
      ElementResponse r;
      e->evaluate(x, x, 1.0, kProps, r, true);
      const MatrixXd dense = history_sensitivity_matrix(r, n, 2);
      const MatrixXd fd_x = test::history_difference(*e, x, kProps, 1e-7);
      for (int j = 0; j < 2; ++j)
        for (int s = 0; s < n; ++s)
          for (int i = 0; i < 2; ++i) {
            const auto column = fd_x.block(0, j * n + s, 2 * n, 1);
            EXPECT_LT((fd_x.block(i * n, j * n + s, n, 1) - dense.block(i * n, j * n + s, n, 1)).cwiseAbs().maxCoeff(),
                      1e-6 * std::max(1.0, column.cwiseAbs().maxCoeff()))
                << "an " << an << " at " << at << " df" << i << "/dx" << j << "(" << s << ")";
          }
      for (int p = 0; p < 4; ++p) {
        const double hp = 1e-7 * std::max(1.0, std::abs(kProps[static_cast<size_t>(p)]));
        const MatrixXd fd = test::property_difference(*e, x, x, kProps, static_cast<size_t>(p), hp);
        EXPECT_LT((fd - r.dforce_dproperty.middleCols(2 * p, 2)).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, fd.cwiseAbs().maxCoeff()))
            << "an " << an << " at " << at << " property " << e->property_names()[static_cast<size_t>(p)];
      }
    }
  }
}

TEST(FrictionalContact, AftJacobianMatchesFiniteDifferences) {
  StructuralModel m;
  m.dof_names = {"n", "t"};
  m.mass = MatrixXd::Identity(2, 2);
  m.stiffness = MatrixXd::Identity(2, 2);
  m.damping = 0.02 * m.stiffness;
  m.forcing.push_back({1, (VectorXd(2) << 0.3, 0.5).finished(), VectorXd::Zero(2)});
  HarmonicBalanceOptions options;
  options.harmonics = 3;
  options.samples = 64;
  options.condensation = Condensation::none;
  HarmonicBalance hbm(m, ElementList{contact({0, 1})}, ParameterSet(), options);
  for (double an : {0.1, 0.4}) {
    VectorXd x = VectorXd::Zero(hbm.unknowns());
    for (int c = 1; c < 7; ++c) {
      x(2 * c) = an / (c * c) * std::cos(0.9 * c);
      x(2 * c + 1) = 0.2 / (c * c) * std::sin(1.7 * c + 0.3);
    }
    EXPECT_LT(test::residual_jacobian_error(hbm, x, 1.1, 1e-7), 1e-6) << "normal amplitude " << an;
  }
}

}  // namespace hbtrack_tests::file_frictional_contact
