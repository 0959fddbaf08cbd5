// tip_contact with friction = "stick_slip": a two-direction Coulomb slider carried by the
// turning casing. Its periodic state against stepping the law from rest, the one-direction case
// against frictional_contact, the limit of a stiff slider on a fast casing against the sliding
// law, and every derivative (sensitivity operator and its transpose, omega, properties, the AFT
// Jacobian) against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/tip_contact.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_tip_contact_stick_slip {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// stiffness, clearance, width, mu, radius, engine_order, rotation_speed, tangential_stiffness
std::vector<double> properties(double engine_order, double rotation_speed, double tangential_stiffness = 20.0) {
  return {5.0, 0.1, 0.5, 0.4, 0.3, engine_order, rotation_speed, tangential_stiffness};
}

std::shared_ptr<TipContact> tip(ContactLawKind law, const std::vector<double>& props) {
  auto e = std::make_shared<TipContact>(law, TipFriction::stick_slip);
  e->dofs = {0, 1, 2};
  for (double p : props) e->properties.push_back(ParameterBinding::constant(p));
  return e;
}

// [radial, theta, z] over one period: contact when x_r > 0.1 (part of the period for ar > 0.1).
MatrixXd motion(int n, double ar, double at) {
  MatrixXd x(n, 3);
  for (int t = 0; t < n; ++t) {
    const double th = 2 * std::numbers::pi * t / n;
    x(t, 0) = 0.1 + ar * std::cos(th + 0.3) + 0.2 * ar * std::sin(2 * th);
    x(t, 1) = at * std::cos(th) + 0.3 * at * std::sin(3 * th + 0.5);
    x(t, 2) = 0.7 * at * std::sin(th + 0.9) - 0.2 * at * std::cos(2 * th);
  }
  return x;
}

// The law stepped sample by sample from rest over many periods; the tangential force of the last.
MatrixXd stepped_force(const TipContact& e, const MatrixXd& x, double omega, const std::vector<double>& props, int periods) {
  const double dt = 2 * std::numbers::pi / omega / static_cast<double>(x.rows());
  VectorXd state = VectorXd::Zero(2);
  MatrixXd force(x.rows(), 3);
  HistoryStep step;
  for (int p = 0; p < periods; ++p)
    for (Eigen::Index t = 0; t < x.rows(); ++t) {
      e.history_step(x.row(t), state, dt, omega, props, step);
      state = step.state;
      force.row(t) = step.force.transpose();
    }
  return force;
}

struct Regime {
  const char* name;
  double ar, at, engine_order;
};
// Separation part of the period without rotation; always in contact without rotation (the
// sqrt law never separates); the casing sliding under the tip.
const Regime kRegimes[] = {
    {"stick-slip with separation", 0.3, 0.15, 0.0}, {"stick-slip, small motion", 0.05, 0.004, 0.0}, {"turning casing", 0.3, 0.15, 1.0}};

}  // namespace

TEST(TipContactStickSlip, PeriodicStateMatchesSteppingTheLawFromRest) {
  // The stepped law forgets its start through separations and slips (in two directions only
  // geometrically): after 40 periods it has reached the periodic state to round-off.
  const double omega = 1.3;
  for (const Regime& r : kRegimes) {
    const std::vector<double> props = properties(r.engine_order, 0.0);
    const auto e = tip(ContactLawKind::polynomial, props);
    const MatrixXd x = motion(128, r.ar, r.at);
    ElementResponse out;
    e->evaluate(x, x, omega, props, out, false);
    EXPECT_LT((out.force - stepped_force(*e, x, omega, props, 40)).cwiseAbs().maxCoeff(), 1e-10) << r.name;
  }
}

TEST(TipContactStickSlip, OneDirectionWithoutRotationIsFrictionalContact) {
  // No axial motion, no rotation, the penalty law: frictional_contact with kn = k and the
  // preload -k clearance, to round-off.
  const std::vector<double> props = properties(0.0, 0.0);
  const auto e = tip(ContactLawKind::penalty, props);
  MatrixXd x = motion(128, 0.3, 0.15);
  x.col(2).setZero();
  FrictionalContact contact;
  contact.dofs = {0, 1};
  ElementResponse a, b;
  e->evaluate(x, x, 1.0, props, a, false);
  contact.evaluate(x.leftCols(2), x.leftCols(2), 1.0, {props[0], props[7], props[3], -props[0] * props[1]}, b, false);
  EXPECT_LT((a.force.leftCols(2) - b.force).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(a.force.col(2).cwiseAbs().maxCoeff(), 0.0);
}

TEST(TipContactStickSlip, StiffSliderOnAFastCasingTendsToTheSlidingLaw) {
  // With the casing sliding fast the tip slips all the time, and the slider's force points
  // along its trial T_prev + k_t (increment of x + casing advance): as k_t grows, along the
  // sample increment of the relative motion. That is eqs 47-48 with the velocity taken as the
  // backward difference over a sample; the lag of the direction, mu N / k_t against the advance
  // per sample, makes the difference fall as 1 / k_t.
  const double omega = 1.0, engine_order = 20.0;
  const int n = 256;
  const MatrixXd x = motion(n, 0.3, 0.15);
  MatrixXd v(n, 3);
  for (int t = 0; t < n; ++t) v.row(t) = (x.row(t) - x.row((t + n - 1) % n)) * (n * omega / (2 * std::numbers::pi));
  TipContact sliding(ContactLawKind::polynomial);
  sliding.dofs = {0, 1, 2};
  std::vector<double> sliding_props = properties(engine_order, 0.0);
  sliding_props.pop_back();
  ElementResponse reference;
  sliding.evaluate(x, v, omega, sliding_props, reference, false);
  double previous = INFINITY;
  for (double kt : {1e2, 1e3, 1e4}) {
    const std::vector<double> props = properties(engine_order, 0.0, kt);
    ElementResponse out;
    tip(ContactLawKind::polynomial, props)->evaluate(x, v, omega, props, out, false);
    const double error = (out.force - reference.force).cwiseAbs().maxCoeff() / reference.force.cwiseAbs().maxCoeff();
    std::printf("[ measured ] k_t = %.0e: stick-slip against sliding %.3e of the largest force\n", kt, error);
    EXPECT_LT(error, 0.2 * previous) << "k_t = " << kt;  // 1/10 per decade
    previous = error;
  }
}

TEST(TipContactStickSlip, DerivativesMatchFiniteDifferences) {
  // Element level. At a fixed stick-slip pattern the force is smooth in x (affine in one
  // direction, the disc's curvature in two): central differences with h = 1e-7 have an
  // O(h^2 / slip deflection) error well below 1e-6 relative.
  const int n = 64;
  const double omega = 1.3, h = 1e-7;
  for (const Regime& r : kRegimes) {
    const std::vector<double> props = properties(r.engine_order, 0.2);
    const auto e = tip(ContactLawKind::polynomial, props);
    const MatrixXd x = motion(n, r.ar, r.at);
    ElementResponse out;
    e->evaluate(x, x, omega, props, out, true);
    const MatrixXd sensitivity = history_sensitivity_matrix(out, n, 3);
    auto force = [&](const MatrixXd& y, double w, const std::vector<double>& p) {
      ElementResponse o;
      e->evaluate(y, y, w, p, o, false);
      return o.force;
    };
    auto check = [&](const MatrixXd& fd, const MatrixXd& analytic, const std::string& what) {
      EXPECT_LT((fd - analytic).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, fd.cwiseAbs().maxCoeff())) << r.name << ": " << what;
    };
    for (int j = 0; j < 3; ++j)
      for (int s = 0; s < n; ++s) {
        MatrixXd xp = x, xm = x;
        xp(s, j) += h, xm(s, j) -= h;
        const MatrixXd fd = (force(xp, omega, props) - force(xm, omega, props)) / (2 * h);
        for (int i = 0; i < 3; ++i)
          check(fd.col(i), sensitivity.block(i * n, j * n + s, n, 1), "df" + std::to_string(i) + "/dx" + std::to_string(j));
      }
    // The transpose the adjoint products use.
    const MatrixXd w = MatrixXd::Random(3 * n, 2);
    EXPECT_LT((out.history_operator->apply_transpose(w) - sensitivity.transpose() * w).cwiseAbs().maxCoeff(), 1e-10) << r.name;
    check((force(x, omega + h, props) - force(x, omega - h, props)) / (2 * h), out.dforce_domega, "df/domega");
    for (size_t p = 0; p < props.size(); ++p) {
      const double hp = 1e-7 * std::max(1.0, std::abs(props[p]));
      check(test::property_difference(*e, x, x, props, p, hp, omega), out.dforce_dproperty.middleCols(3 * static_cast<Eigen::Index>(p), 3),
            "df/d" + e->property_names()[p]);
    }
  }
}

TEST(TipContactStickSlip, AftJacobianMatchesFiniteDifferences) {
  // A tip node on three unit oscillators, condensation off; residual and its Jacobian, and the
  // adjoint product limit-point tracking uses.
  StructuralModel m;
  m.dof_names = {"r", "theta", "z"};
  m.mass = MatrixXd::Identity(3, 3);
  m.stiffness = MatrixXd::Identity(3, 3);
  m.damping = 0.02 * m.stiffness;
  m.forcing.push_back({1, (VectorXd(3) << 0.3, 0.5, 0.2).finished(), VectorXd::Zero(3)});
  for (const Regime& r : kRegimes) {
    const std::vector<double> props = properties(r.engine_order, 0.0);
    HarmonicBalance hbm(m, ElementList{tip(ContactLawKind::polynomial, props)}, ParameterSet(),
                        HarmonicBalanceOptions{3, 64, Condensation::none, {}, 1, {}});
    VectorXd x = VectorXd::Zero(hbm.unknowns());
    x(0) = 0.2;  // the mean radial position, 0.1, at the clearance
    for (int c = 1; c < 7; ++c) {
      x(3 * c) = r.ar / (c * c) * std::cos(0.9 * c);
      x(3 * c + 1) = r.at / (c * c) * std::sin(1.7 * c + 0.3);
      x(3 * c + 2) = 0.5 * r.at / (c * c) * std::cos(0.4 * c + 1.0);
    }
    EXPECT_LT(test::residual_jacobian_error(hbm, x, 1.1, 1e-7), 1e-6) << r.name;
    const MatrixXd fd_nl = test::fd_jacobian([&](const VectorXd& y) { return hbm.nonlinear_forces(y, 1.1); }, x, 1e-7);
    const VectorXd w = VectorXd::LinSpaced(x.size(), -1.0, 2.0);
    VectorXd jt_w;
    hbm.nonlinear_adjoint_products(x, 1.1, w, jt_w);
    EXPECT_LT(test::relative_error(jt_w, fd_nl.transpose() * w), 1e-6) << r.name;
  }
}

TEST(TipContactStickSlip, StuckSliderMeetsTheSlippingOneAtTheThreshold) {
  // Below some tangential amplitude the slider can stick all period, anywhere within
  // mu N(t) / k_t of every x(t); it is put at the position of largest margin, which is where the
  // slipping state arrives as the amplitude falls to the threshold. With a varying N the
  // midrange of x (or the centre of its box, in two directions) is not: it would make the force
  // jump there. The threshold is found by bisection on "the force stays inside the disc at every
  // sample"; across it (amplitude * (1 +- 1e-9)) the force may only move by ~1e-9 of its size.
  const double omega = 1.0;
  const std::vector<double> props = properties(0.0, 0.0);
  MatrixXd shape = motion(128, 0.05, 0.01);  // always in contact (the polynomial law's blend)
  shape.col(0).array() -= 0.1;
  for (int directions : {1, 2}) {
    const auto e = tip(ContactLawKind::polynomial, props);
    auto force = [&](double scale) {
      MatrixXd x = shape;
      x.col(0).array() += 0.1;
      x.rightCols(2) *= scale;
      if (directions == 1) x.col(2).setZero();
      ElementResponse out;
      e->evaluate(x, x, omega, props, out, false);
      return out.force;
    };
    auto sticks = [&](double scale) {
      const MatrixXd f = force(scale);
      for (Eigen::Index t = 0; t < f.rows(); ++t)
        if (f.row(t).tail(2).norm() >= (1 - 1e-12) * props[3] * f(t, 0)) return false;
      return true;
    };
    double low = 0.1, high = 100.0;
    ASSERT_TRUE(sticks(low));
    ASSERT_FALSE(sticks(high));
    for (int i = 0; i < 200 && high - low > 1e-14 * high; ++i) (sticks(0.5 * (low + high)) ? low : high) = 0.5 * (low + high);
    const MatrixXd below = force(high * (1 - 1e-9)), above = force(high * (1 + 1e-9));
    EXPECT_LT((below - above).cwiseAbs().maxCoeff(), 1e-7 * above.cwiseAbs().maxCoeff()) << directions << " direction(s)";
  }
}

}  // namespace hbtrack_tests::file_tip_contact_stick_slip
