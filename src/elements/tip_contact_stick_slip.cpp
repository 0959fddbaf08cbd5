// tip_contact with friction = "stick_slip": the regularised normal law of the sliding variant
// and a two-direction Coulomb slider (coulomb_slider.hpp) that the turning casing carries along.
#include <cmath>
#include <memory>
#include <numbers>

#include "coulomb_slider.hpp"
#include "hbtrack/elements/tip_contact.hpp"

namespace hbtrack {

namespace {

enum Property { kStiffness, kClearance, kWidth, kMu, kRadius, kEngineOrder, kRotationSpeed, kTangentialStiffness, kCount };

// The casing's advance over one sample interval of the period, rho W T / N (W = eo omega +
// rotation_speed, T = 2 pi / omega), and its derivatives with respect to omega, radius,
// engine_order and rotation_speed.
struct CasingAdvance {
  double value, d_omega, d_radius, d_engine_order, d_rotation_speed;
};
CasingAdvance casing_advance(const std::vector<double>& p, double omega, Eigen::Index samples) {
  const double per_sample = 2.0 * std::numbers::pi / static_cast<double>(samples);
  const double rho = p[kRadius], eo = p[kEngineOrder], spin = p[kRotationSpeed];
  return {rho * (eo + spin / omega) * per_sample, -rho * spin / (omega * omega) * per_sample, (eo + spin / omega) * per_sample,
          rho * per_sample, rho / omega * per_sample};
}

Eigen::VectorXd drift_of(double advance) { return Eigen::Vector2d(advance, 0.0); }

}  // namespace

void TipContact::evaluate_stick_slip(const Eigen::MatrixXd& x, double omega, const std::vector<double>& p, ElementResponse& out,
                                     bool want_property_derivatives) const {
  const Eigen::Index n = x.rows();
  constexpr int k = 3;
  Eigen::VectorXd normal(n), slope(n);
  std::vector<ContactForce> contact(static_cast<size_t>(n));
  for (Eigen::Index t = 0; t < n; ++t) {
    contact[static_cast<size_t>(t)] = contact_force(kind_, x(t, 0) - p[kClearance], p[kStiffness], p[kWidth]);
    normal(t) = contact[static_cast<size_t>(t)].force;
    slope(t) = contact[static_cast<size_t>(t)].d_gap;
  }
  const CasingAdvance advance = casing_advance(p, omega, n);
  CoulombSlider slider(2, p[kTangentialStiffness], p[kMu]);
  slider.solve_period(normal, x.rightCols(2), drift_of(advance.value));

  out.force.resize(n, k);
  out.force.col(0) = normal;
  for (Eigen::Index t = 0; t < n; ++t) out.force.row(t).tail(2) = slider.steps()[static_cast<size_t>(t)].force.transpose();
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.history_dforce_dx.resize(0, 0);
  // omega moves the casing (through rotation_speed / omega); each property perturbs the
  // slider's inputs: the normal law's through N, the rotation's through the casing's advance.
  const int q = slider.inputs();
  const int cases = want_property_derivatives ? 1 + kCount : 1;
  Eigen::MatrixXd dv = Eigen::MatrixXd::Zero(n * q, cases);
  for (Eigen::Index t = 0; t < n; ++t) {
    const ContactForce& c = contact[static_cast<size_t>(t)];
    const Eigen::Index row = t * q;
    dv(row + slider.drift_input(0), 0) = advance.d_omega;
    if (!want_property_derivatives) continue;
    dv(row + slider.normal_input(), 1 + kStiffness) = c.d_stiffness;
    dv(row + slider.normal_input(), 1 + kClearance) = -c.d_gap;
    dv(row + slider.normal_input(), 1 + kWidth) = c.d_width;
    dv(row + slider.mu_input(), 1 + kMu) = 1.0;
    dv(row + slider.drift_input(0), 1 + kRadius) = advance.d_radius;
    dv(row + slider.drift_input(0), 1 + kEngineOrder) = advance.d_engine_order;
    dv(row + slider.drift_input(0), 1 + kRotationSpeed) = advance.d_rotation_speed;
    dv(row + slider.stiffness_input(), 1 + kTangentialStiffness) = 1.0;
  }
  const Eigen::MatrixXd dt = slider.periodic_response(dv);
  out.dforce_domega.setZero(n, k);
  for (Eigen::Index t = 0; t < n; ++t) out.dforce_domega.row(t).tail(2) = dt.block(2 * t, 0, 2, 1).transpose();
  if (want_property_derivatives) {
    out.dforce_dproperty.setZero(n, k * kCount);
    for (int prop = 0; prop < kCount; ++prop)
      for (Eigen::Index t = 0; t < n; ++t) {
        out.dforce_dproperty(t, k * prop) = dv(t * q + slider.normal_input(), 1 + prop);
        out.dforce_dproperty(t, 1 + k * prop) = dt(2 * t, 1 + prop);
        out.dforce_dproperty(t, 2 + k * prop) = dt(2 * t + 1, 1 + prop);
      }
  }
  out.history_operator = std::make_shared<ContactSliderSensitivity>(std::move(slider), std::move(slope));
}

void TipContact::history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega, const std::vector<double>& p,
                              HistoryStep& out) const {
  if (friction_ != TipFriction::stick_slip) {
    NonlinearElement::history_step(x, state, dt, omega, p, out);
    return;
  }
  const ContactForce c = contact_force(kind_, x(0, 0) - p[kClearance], p[kStiffness], p[kWidth]);
  const double advance = p[kRadius] * (p[kEngineOrder] * omega + p[kRotationSpeed]) * dt;
  contact_slider_step(CoulombSlider(2, p[kTangentialStiffness], p[kMu]), c.force, c.d_gap, x, drift_of(advance), state, out);
}

Eigen::MatrixXd TipContact::periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& p) const {
  if (friction_ != TipFriction::stick_slip) return NonlinearElement::periodic_history(x, omega, p);
  Eigen::VectorXd normal(x.rows());
  for (Eigen::Index t = 0; t < x.rows(); ++t) normal(t) = contact_force(kind_, x(t, 0) - p[kClearance], p[kStiffness], p[kWidth]).force;
  CoulombSlider slider(2, p[kTangentialStiffness], p[kMu]);
  slider.solve_period(normal, x.rightCols(2), drift_of(casing_advance(p, omega, x.rows()).value));
  Eigen::MatrixXd states(x.rows(), 2);
  for (Eigen::Index t = 0; t < x.rows(); ++t) states.row(t) = slider.steps()[static_cast<size_t>(t)].state.transpose();
  return states;
}

}  // namespace hbtrack
