// elastic_dry_friction_2d: a Jenkins slider in a plane. The steady circular orbit against its
// closed form (the continuous law's and the sampled return mapping's), motion along one axis
// against elastic_dry_friction, the periodic state against stepping the law from rest, the
// sensitivities, their transpose and the AFT Jacobian against finite differences, and
// history_step against the periodic pass.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "hbtrack/elements/elastic_dry_friction.hpp"
#include "hbtrack/elements/elastic_dry_friction_2d.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_elastic_dry_friction_2d {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

constexpr double kStiffness = 20.0, kLimit = 1.0;  // F / k = 0.05
const std::vector<double> kProps{kStiffness, kLimit};

std::shared_ptr<ElasticDryFriction2D> planar(std::vector<int> dofs, MatrixXd weights) {
  auto e = std::make_shared<ElasticDryFriction2D>();
  e->dofs = std::move(dofs);
  e->weights = std::move(weights);
  for (double p : kProps) e->properties.push_back(ParameterBinding::constant(p));
  return e;
}

std::shared_ptr<ElasticDryFriction2D> grounded() { return planar({0, 1}, MatrixXd::Identity(2, 2)); }

// u = r (cos theta, sin theta) at theta_t = 2 pi t / n.
MatrixXd circle(int n, double r) {
  MatrixXd u(n, 2);
  for (int t = 0; t < n; ++t) {
    const double th = 2 * std::numbers::pi * t / n;
    u(t, 0) = r * std::cos(th);
    u(t, 1) = r * std::sin(th);
  }
  return u;
}

// A planar motion with higher harmonics, amplitude a.
MatrixXd wobble(int n, double a) {
  MatrixXd u(n, 2);
  for (int t = 0; t < n; ++t) {
    const double th = 2 * std::numbers::pi * t / n;
    u(t, 0) = a * (std::cos(th) + 0.3 * std::sin(2 * th + 0.4));
    u(t, 1) = a * (0.6 * std::sin(th + 0.2) - 0.25 * std::cos(3 * th));
  }
  return u;
}

// The law written out, stepped from rest (slider at 0) over `periods` periods: the last one.
MatrixXd stepped_from_rest(const MatrixXd& u, int periods) {
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  MatrixXd force(u.rows(), 2);
  for (int p = 0; p < periods; ++p)
    for (Eigen::Index t = 0; t < u.rows(); ++t) {
      const Eigen::Vector2d ut = u.row(t).transpose();
      Eigen::Vector2d trial = kStiffness * (ut - z);
      if (trial.norm() > kLimit) {
        trial *= kLimit / trial.norm();
        z = ut - trial / kStiffness;
      }
      force.row(t) = trial.transpose();
    }
  return force;
}

}  // namespace

TEST(ElasticDryFriction2D, CircularOrbitSlidesWithTheClosedFormLagAndMagnitude) {
  // u = r (cos wt, sin wt), s = F / (k r) < 1. Continuous law: in steady sliding the slider z
  // turns on a circle with u, and slips along T = k (u - z), tangent to its circle: z is
  // perpendicular to u - z, so |z| = sqrt(r^2 - (F/k)^2), |T| = F, and T leads u by
  // alpha = arccos(s) (z lags u by arcsin(s)). The sampled return mapping (Delta = 2 pi / N):
  // by symmetry T_t = F g e^(i theta_t) with, from T* = k (u_t - z_(t-1)) parallel to g,
  //   g = i a e^(-i Delta/2) / (m - s e^(-i Delta)),  a = 2 sin(Delta/2),
  //   m = s cos(Delta) + sqrt(a^2 - s^2 sin^2(Delta)),  |g| = 1,
  // arg g = alpha - Delta/2 + s Delta^2 / (8 sqrt(1 - s^2)) + O(Delta^4): the sampled slider
  // lags half a sample behind the continuous one (the return mapping is backward Euler in the
  // flow), an O(1/N) phase error of the AFT's time half.
  const auto e = grounded();
  for (double s : {0.5, 0.8}) {
    const double r = kLimit / (kStiffness * s), alpha = std::acos(s);
    for (int n : {64, 256, 1024}) {
      const double delta = 2 * std::numbers::pi / n, a = 2 * std::sin(delta / 2);
      const double m = s * std::cos(delta) + std::sqrt(a * a - s * s * std::sin(delta) * std::sin(delta));
      const std::complex<double> g = std::complex<double>(0, a) * std::polar(1.0, -delta / 2) / (m - s * std::polar(1.0, -delta));
      const MatrixXd u = circle(n, r);
      ElementResponse out;
      e->evaluate(u, u, 1.0, kProps, out, false);
      double worst = 0, magnitude = 0;
      for (int t = 0; t < n; ++t) {
        const std::complex<double> expected = kLimit * g * std::polar(1.0, delta * t);
        worst = std::max(worst, std::abs(std::complex<double>(out.force(t, 0), out.force(t, 1)) - expected));
        magnitude = std::max(magnitude, std::abs(out.force.row(t).norm() - kLimit));
      }
      const double lead = std::arg(g), series = alpha - delta / 2 + s * delta * delta / (8 * std::sqrt(1 - s * s));
      std::printf("[ measured ] s %.1f N %4d: force vs sampled closed form %.1e, |T| - F %.1e, lead - arccos(s) %.3e (-pi/N %.3e)\n", s, n,
                  worst / kLimit, magnitude / kLimit, lead - alpha, -delta / 2);
      EXPECT_LT(worst, 1e-12 * kLimit) << "s " << s << " N " << n;
      EXPECT_LT(magnitude, 1e-12 * kLimit) << "s " << s << " N " << n;
      EXPECT_NEAR(std::abs(g), 1.0, 1e-12);
      EXPECT_LT(std::abs(lead - series), std::pow(delta, 4)) << "s " << s << " N " << n;
    }
  }
  // Below the threshold (k r < F) the slider sticks all period at the circle's centre: T = k u.
  const MatrixXd small = circle(128, 0.5 * kLimit / kStiffness);
  ElementResponse out;
  e->evaluate(small, small, 1.0, kProps, out, false);
  EXPECT_LT((out.force - kStiffness * small).cwiseAbs().maxCoeff(), 1e-12 * kLimit);
}

TEST(ElasticDryFriction2D, MotionAlongOneDirectionIsElasticDryFriction) {
  // u along a fixed unit direction e (the x axis, then a rotated one): the slider moves along
  // e, T = f e with f the 1D Jenkins force of d = e.u, in stick (range < 2 F / k) and slip.
  ElasticDryFriction jenkins;
  jenkins.dofs = {0};
  jenkins.weights = VectorXd::Ones(1);
  const auto e = grounded();
  for (double angle : {0.0, 0.7}) {
    const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
    for (double amplitude : {0.02, 0.3}) {
      const int n = 256;
      MatrixXd d(n, 1);
      for (int t = 0; t < n; ++t) {
        const double th = 2 * std::numbers::pi * t / n;
        d(t, 0) = amplitude * (std::cos(th) + 0.4 * std::sin(3 * th + 0.2)) + 0.1;
      }
      const MatrixXd u = d * dir.transpose();
      ElementResponse a, b;
      e->evaluate(u, u, 1.0, kProps, a, false);
      jenkins.evaluate(d, d, 1.0, kProps, b, false);
      EXPECT_LT((a.force - b.force * dir.transpose()).cwiseAbs().maxCoeff(), 1e-12 * kLimit)
          << "angle " << angle << " amplitude " << amplitude;
    }
  }
}

TEST(ElasticDryFriction2D, PeriodicStateMatchesSteppingTheLawFromRest) {
  // In two directions the memory fades geometrically through slip (by F / |T*| across the
  // sliding direction per slip sample) rather than ending: 60 periods from rest bring the
  // stepped law to the periodic state to round-off for these motions.
  const auto e = grounded();
  for (double a : {0.08, 0.3, 1.0}) {
    const MatrixXd u = wobble(200, a);
    ElementResponse out;
    e->evaluate(u, u, 1.0, kProps, out, false);
    EXPECT_LT((out.force - stepped_from_rest(u, 60)).cwiseAbs().maxCoeff(), 1e-10 * kLimit) << "amplitude " << a;
  }
}

TEST(ElasticDryFriction2D, SensitivitiesAndTheirTransposeMatchFiniteDifferences) {
  // Between two nodes along general directions (4 dofs, W 2 x 4). At a fixed stick-slip pattern
  // the sampled law is smooth in x (affine in stick, the radial projection in slip), so central
  // differences with h = 1e-7 agree to about h^2 |T''| + round-off / h, far below 1e-6.
  MatrixXd w(2, 4);
  w << 1.0, 0.3, -1.0, 0.0, -0.2, 0.8, 0.0, -1.1;
  const auto e = planar({0, 1, 2, 3}, w);
  const int n = 64;
  for (double a : {0.03, 0.3}) {
    MatrixXd x(n, 4);
    const MatrixXd u1 = wobble(n, a), u2 = wobble(n, 0.4 * a);
    x << u1, u2.rowwise().reverse();
    ElementResponse r;
    e->evaluate(x, x, 1.0, kProps, r, true);
    ASSERT_TRUE(r.history_operator);
    const MatrixXd dense = history_sensitivity_matrix(r, n, 4);
    const MatrixXd fd = test::history_difference(*e, x, kProps, 1e-7);
    EXPECT_LT((fd - dense).cwiseAbs().maxCoeff(), 1e-6 * kStiffness) << "amplitude " << a;
    const MatrixXd transposed = r.history_operator->apply_transpose(MatrixXd::Identity(4 * n, 4 * n));
    EXPECT_LT((transposed - dense.transpose()).cwiseAbs().maxCoeff(), 1e-12 * kStiffness) << "amplitude " << a;
    for (size_t p = 0; p < 2; ++p) {
      const MatrixXd fdp = test::property_difference(*e, x, x, kProps, p, 1e-7 * kProps[p]);
      EXPECT_LT((fdp - r.dforce_dproperty.middleCols(4 * static_cast<Eigen::Index>(p), 4)).cwiseAbs().maxCoeff(),
                1e-6 * std::max(1.0, fdp.cwiseAbs().maxCoeff()))
          << "amplitude " << a << " property " << e->property_names()[p];
    }
  }
}

TEST(ElasticDryFriction2D, AftJacobianMatchesFiniteDifferences) {
  // Two orthogonal unit oscillators with the slider to the ground, and three dofs carrying the
  // plane along general directions; in stick-slip and (small amplitude) all-stick.
  struct Setup {
    const char* name;
    int dofs;
    MatrixXd weights;
  };
  const std::vector<Setup> setups{{"grounded [x, y]", 2, MatrixXd::Identity(2, 2)},
                                  {"three dofs", 3, (MatrixXd(2, 3) << 0.6, 0.8, -1.0, -0.8, 0.6, 0.5).finished()}};
  for (const Setup& s : setups) {
    StructuralModel m;
    for (int i = 0; i < s.dofs; ++i) m.dof_names.push_back("x" + std::to_string(i));
    m.mass = MatrixXd::Identity(s.dofs, s.dofs);
    m.stiffness = MatrixXd::Identity(s.dofs, s.dofs);
    m.stiffness(0, 0) = 1.3;
    m.damping = 0.02 * m.stiffness;
    m.forcing.push_back({1, VectorXd::Constant(s.dofs, 0.3), VectorXd::Zero(s.dofs)});
    std::vector<int> dofs;
    for (int i = 0; i < s.dofs; ++i) dofs.push_back(i);
    HarmonicBalanceOptions options;
    options.harmonics = 3;
    options.samples = 64;
    options.condensation = Condensation::none;
    HarmonicBalance hbm(m, ElementList{planar(dofs, s.weights)}, ParameterSet(), options);
    for (double a : {0.01, 0.3}) {
      VectorXd x = VectorXd::Zero(hbm.unknowns());
      for (int c = 1; c < 7; ++c)
        for (int i = 0; i < s.dofs; ++i) x(s.dofs * c + i) = a / (c * c) * std::cos(0.9 * c + 1.3 * i);
      EXPECT_LT(test::residual_jacobian_error(hbm, x, 1.1, 1e-7), 1e-6) << s.name << " amplitude " << a;
    }
  }
}

TEST(ElasticDryFriction2D, SteppingFromThePeriodicHistoryReproducesThePeriodicForces) {
  // history_step (time integration, the monodromy matrix) from the slider after sample t-1 is
  // the periodic pass's return mapping at sample t; its tangents against finite differences.
  MatrixXd w(2, 3);
  w << 1.0, 0.0, -0.5, 0.2, 1.0, 0.0;
  const auto e = planar({0, 1, 2}, w);
  const int n = 128;
  MatrixXd x(n, 3);
  x << wobble(n, 0.2), wobble(n, 0.05).col(0);
  ElementResponse r;
  e->evaluate(x, x, 1.0, kProps, r, false);
  const MatrixXd history = e->periodic_history(x, 1.0, kProps);
  ASSERT_EQ(history.cols(), 2);
  HistoryStep step;
  for (int t = 0; t < n; ++t) {
    const VectorXd previous = history.row((t + n - 1) % n).transpose();
    e->history_step(x.row(t), previous, 0.1, 1.0, kProps, step);
    EXPECT_LT((step.force.transpose() - r.force.row(t)).cwiseAbs().maxCoeff(), 1e-12) << "sample " << t;
    EXPECT_LT((step.state - history.row(t).transpose()).cwiseAbs().maxCoeff(), 1e-12) << "sample " << t;
    // Tangents: with respect to x and to the state before the step.
    const auto force_of = [&](const VectorXd& y) {
      HistoryStep s;
      e->history_step(y.head(3).transpose(), y.tail(2), 0.1, 1.0, kProps, s);
      VectorXd out(5);
      out << s.force, s.state;
      return out;
    };
    VectorXd y(5);
    y << x.row(t).transpose(), previous;
    const MatrixXd fd = test::fd_jacobian(force_of, y, 1e-7);
    MatrixXd analytic(5, 5);
    analytic << step.dforce_dx, step.dforce_dstate, step.dstate_dx, step.dstate_dstate;
    EXPECT_LT((fd - analytic).cwiseAbs().maxCoeff(), 1e-6 * kStiffness) << "sample " << t;
  }
}

}  // namespace hbtrack_tests::file_elastic_dry_friction_2d
