// frictional_contact_2d: a penalty normal load N(t) from the normal dof and a Jenkins slider of
// limit mu N(t) slipping in the tangential plane, free when separated. The constant-load case
// against elastic_dry_friction_2d, motion along one tangential axis against frictional_contact,
// the periodic state against stepping the law from rest, and the sensitivities, the property
// derivatives and the AFT Jacobian against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/elements/elastic_dry_friction_2d.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_frictional_contact_2d {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// normal_stiffness, tangential_stiffness, mu, normal_preload
const std::vector<double> kProps{5.0, 20.0, 0.4, 1.0};

std::shared_ptr<FrictionalContact> contact() {
  auto e = std::make_shared<FrictionalContact>(ContactFormulation::penalty, 2);
  e->dofs = {0, 1, 2};
  for (double p : kProps) e->properties.push_back(ParameterBinding::constant(p));
  return e;
}

// [x_n, x_t1, x_t2] over one period: normal amplitude an (separation when 5 an > 1), an
// elliptic tangential motion of amplitude at with higher harmonics.
MatrixXd motion(int n, double an, double at) {
  MatrixXd x(n, 3);
  for (int t = 0; t < n; ++t) {
    const double th = 2 * std::numbers::pi * t / n;
    x(t, 0) = an * std::cos(th + 0.3) + 0.2 * an * std::sin(2 * th);
    x(t, 1) = at * (std::cos(th) + 0.3 * std::sin(3 * th + 0.5));
    x(t, 2) = at * (0.7 * std::sin(th + 0.4) - 0.2 * std::cos(2 * th));
  }
  return x;
}

// The law stepped from rest over `periods` periods: the tangential forces of the last one.
MatrixXd stepped_from_rest(const MatrixXd& x, int periods) {
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  MatrixXd force(x.rows(), 2);
  for (int p = 0; p < periods; ++p)
    for (Eigen::Index t = 0; t < x.rows(); ++t) {
      const Eigen::Vector2d xt = x.row(t).tail(2).transpose();
      const double normal = std::max(0.0, kProps[3] + kProps[0] * x(t, 0));
      Eigen::Vector2d trial = kProps[1] * (xt - z);
      if (normal <= 0.0) {
        z = xt;
        trial.setZero();
      } else if (trial.norm() > kProps[2] * normal) {
        trial *= kProps[2] * normal / trial.norm();
        z = xt - trial / kProps[1];
      }
      force.row(t) = trial.transpose();
    }
  return force;
}

}  // namespace

TEST(FrictionalContact2D, ConstantNormalLoadIsThePlanarJenkinsElement) {
  // x_n = 0: N = preload, limit mu * preload; in stick (range < 2 mu N / kt) and in slip.
  ElasticDryFriction2D planar;
  planar.dofs = {0, 1};
  planar.weights = MatrixXd::Identity(2, 2);
  for (double at : {0.005, 0.3}) {
    const MatrixXd x = motion(128, 0.0, at);
    ElementResponse a, b;
    contact()->evaluate(x, x, 1.0, kProps, a, false);
    planar.evaluate(x.rightCols(2), x.rightCols(2), 1.0, {kProps[1], kProps[2] * kProps[3]}, b, false);
    EXPECT_LT((a.force.rightCols(2) - b.force).cwiseAbs().maxCoeff(), 1e-12) << "amplitude " << at;
  }
}

TEST(FrictionalContact2D, MotionAlongOneTangentialAxisIsFrictionalContact) {
  auto one = std::make_shared<FrictionalContact>();
  one->dofs = {0, 1};
  for (double an : {0.1, 0.4}) {  // always in contact, separating
    MatrixXd x = motion(128, an, 0.2);
    x.col(2).setZero();
    ElementResponse a, b;
    contact()->evaluate(x, x, 1.0, kProps, a, false);
    one->evaluate(x.leftCols(2), x.leftCols(2), 1.0, kProps, b, false);
    EXPECT_LT((a.force.leftCols(2) - b.force).cwiseAbs().maxCoeff(), 1e-12) << "normal amplitude " << an;
    EXPECT_EQ(a.force.col(2).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(FrictionalContact2D, PeriodicStateMatchesSteppingTheLawFromRest) {
  // A separation erases the memory; slip in the plane only fades it: 60 periods from rest.
  // (A slider that sticks all period keeps wherever the transient left it: the element's choice,
  // the position of largest margin, is not the stepped law's, and is not compared here.)
  const auto e = contact();
  struct Regime {
    const char* name;
    double an, at;
  };
  for (const Regime& r : {Regime{"slip, always in contact", 0.1, 0.2}, Regime{"separation", 0.4, 0.2},
                          Regime{"separation, small tangential motion", 0.4, 0.004}}) {
    const MatrixXd x = motion(200, r.an, r.at);
    ElementResponse out;
    e->evaluate(x, x, 1.0, kProps, out, false);
    EXPECT_LT((out.force.rightCols(2) - stepped_from_rest(x, 60)).cwiseAbs().maxCoeff(), 1e-10) << r.name;
  }
}

TEST(FrictionalContact2D, DerivativesMatchFiniteDifferences) {
  // At a fixed pattern of stick, slip and separation the sampled law is smooth in x and in each
  // property: central differences with h = 1e-7 agree to ~1e-9 relative.
  const auto e = contact();
  const int n = 64;
  for (double an : {0.1, 0.4})
    for (double at : {0.004, 0.2}) {
      const MatrixXd x = motion(n, an, at);
      ElementResponse r;
      e->evaluate(x, x, 1.0, kProps, r, true);
      const MatrixXd fd = test::history_difference(*e, x, kProps, 1e-7);
      EXPECT_LT((fd - history_sensitivity_matrix(r, n, 3)).cwiseAbs().maxCoeff(), 1e-6 * kProps[1]) << "an " << an << " at " << at;
      for (size_t p = 0; p < 4; ++p) {
        const MatrixXd fdp = test::property_difference(*e, x, x, kProps, p, 1e-7 * std::max(1.0, kProps[p]));
        EXPECT_LT((fdp - r.dforce_dproperty.middleCols(3 * static_cast<Eigen::Index>(p), 3)).cwiseAbs().maxCoeff(),
                  1e-6 * std::max(1.0, fdp.cwiseAbs().maxCoeff()))
            << "an " << an << " at " << at << " property " << e->property_names()[p];
      }
    }
}

TEST(FrictionalContact2D, AftJacobianMatchesFiniteDifferences) {
  StructuralModel m;
  m.dof_names = {"n", "t1", "t2"};
  m.mass = MatrixXd::Identity(3, 3);
  m.stiffness = Eigen::Vector3d(1.0, 1.0, 1.44).asDiagonal();
  m.damping = 0.02 * m.stiffness;
  m.forcing.push_back({1, Eigen::Vector3d(0.3, 0.5, 0.2), VectorXd::Zero(3)});
  HarmonicBalanceOptions options;
  options.harmonics = 3;
  options.samples = 64;
  options.condensation = Condensation::none;
  HarmonicBalance hbm(m, ElementList{contact()}, ParameterSet(), options);
  for (double an : {0.1, 0.4}) {
    VectorXd x = VectorXd::Zero(hbm.unknowns());
    for (int c = 1; c < 7; ++c) {
      x(3 * c) = an / (c * c) * std::cos(0.9 * c);
      x(3 * c + 1) = 0.2 / (c * c) * std::sin(1.7 * c + 0.3);
      x(3 * c + 2) = 0.15 / (c * c) * std::cos(1.1 * c + 0.6);
    }
    EXPECT_LT(test::residual_jacobian_error(hbm, x, 1.1, 1e-7), 1e-6) << "normal amplitude " << an;
  }
}

}  // namespace hbtrack_tests::file_frictional_contact_2d
