#include "hbtrack/elements/tip_contact.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

namespace {
enum Property { kStiffness, kClearance, kWidth, kMu, kRadius, kEngineOrder, kRotationSpeed, kCount };
enum Local { kR = 0, kTheta = 1, kZ = 2 };
}  // namespace

TipFriction parse_tip_friction(const std::string& name) {
  if (name == "sliding") return TipFriction::sliding;
  if (name == "stick_slip") return TipFriction::stick_slip;
  throw std::invalid_argument("must be \"sliding\" or \"stick_slip\", got \"" + name + "\"");
}

std::string to_string(TipFriction friction) { return friction == TipFriction::sliding ? "sliding" : "stick_slip"; }

const std::vector<std::string>& TipContact::property_names() const {
  static const std::vector<std::string> sliding{"stiffness", "clearance", "width", "mu", "radius", "engine_order", "rotation_speed"};
  static const std::vector<std::string> stick_slip{"stiffness", "clearance",    "width",          "mu",
                                                   "radius",    "engine_order", "rotation_speed", "tangential_stiffness"};
  return friction_ == TipFriction::sliding ? sliding : stick_slip;
}

bool TipContact::force_has_corners() const { return friction_ == TipFriction::stick_slip || kind_ == ContactLawKind::penalty; }

std::string TipContact::smoothness_limit() const {
  if (friction_ == TipFriction::sliding) return hbtrack::smoothness_limit(kind_);
  return "stick-slip transitions make the friction force non-smooth";
}

int TipContact::switching_surfaces(const std::vector<double>& p) const {
  return kind_ == ContactLawKind::penalty || p[kWidth] <= 0.0 ? 1 : 0;
}

void TipContact::switching_values(const Eigen::MatrixXd& x, const Eigen::MatrixXd&, const std::vector<double>& p, double* out) const {
  out[0] = x(0, kR) - p[kClearance];
}

std::optional<FrictionCoupling> TipContact::friction_coupling(const std::vector<double>& p, double omega) const {
  // The element's force is the structure's internal one: the casing pushes the tip with
  // -mu f_N sign(v_theta + rho W) along theta, -sign(W) at rest.
  const double rotation = p[kEngineOrder] * omega + p[kRotationSpeed];
  const int sense = rotation > 0 ? -1 : rotation < 0 ? 1 : 0;
  return FrictionCoupling{kR, kTheta, p[kMu], p[kStiffness], sense};
}

void TipContact::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& p,
                          ElementResponse& out, bool want_property_derivatives) const {
  if (friction_ == TipFriction::stick_slip) {
    evaluate_stick_slip(x, omega, p, out, want_property_derivatives);
    return;
  }
  evaluate_sliding(x, v, omega, p, out, want_property_derivatives);
}

void TipContact::evaluate_sliding(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& p,
                                  ElementResponse& out, bool want_property_derivatives) const {
  const Eigen::Index n = x.rows();
  constexpr int k = 3;
  out.force.setZero(n, k);
  out.dforce_dx.setZero(n, k * k);
  out.dforce_dv.setZero(n, k * k);
  out.dforce_domega.setZero(n, k);
  if (want_property_derivatives) out.dforce_dproperty.setZero(n, k * kCount);
  const double mu = p[kMu], rho = p[kRadius];
  const double rotation = p[kEngineOrder] * omega + p[kRotationSpeed];
  for (Eigen::Index t = 0; t < n; ++t) {
    const ContactForce c = contact_force(kind_, x(t, kR) - p[kClearance], p[kStiffness], p[kWidth]);
    if (c.force == 0.0 && c.d_gap == 0.0 && c.d_width == 0.0) continue;  // out of contact
    const double vt = v(t, kTheta) + rho * rotation;
    const double vz = v(t, kZ);
    const double speed = std::hypot(vt, vz);
    // Sliding direction and its derivatives; with no sliding speed friction has no direction.
    double ut = 0, uz = 0, dut_dvt = 0, dut_dvz = 0, duz_dvt = 0, duz_dvz = 0;
    if (speed > 0.0) {
      const double s3 = speed * speed * speed;
      ut = vt / speed;
      uz = vz / speed;
      dut_dvt = vz * vz / s3;
      dut_dvz = -vt * vz / s3;
      duz_dvt = dut_dvz;
      duz_dvz = vt * vt / s3;
    }
    const double fn = c.force;
    out.force(t, kR) = fn;
    out.force(t, kTheta) = mu * fn * ut;
    out.force(t, kZ) = mu * fn * uz;
    // Only the radial displacement enters (through the gap).
    out.dforce_dx(t, kR + k * kR) = c.d_gap;
    out.dforce_dx(t, kTheta + k * kR) = mu * c.d_gap * ut;
    out.dforce_dx(t, kZ + k * kR) = mu * c.d_gap * uz;
    out.dforce_dv(t, kTheta + k * kTheta) = mu * fn * dut_dvt;
    out.dforce_dv(t, kTheta + k * kZ) = mu * fn * dut_dvz;
    out.dforce_dv(t, kZ + k * kTheta) = mu * fn * duz_dvt;
    out.dforce_dv(t, kZ + k * kZ) = mu * fn * duz_dvz;
    // omega drives the rotation speed, hence the circumferential sliding speed.
    const double dvt_domega = rho * p[kEngineOrder];
    out.dforce_domega(t, kTheta) = mu * fn * dut_dvt * dvt_domega;
    out.dforce_domega(t, kZ) = mu * fn * duz_dvt * dvt_domega;
    if (!want_property_derivatives) continue;
    auto normal_part = [&](int prop, double dfn) {
      out.dforce_dproperty(t, kR + k * prop) = dfn;
      out.dforce_dproperty(t, kTheta + k * prop) = mu * dfn * ut;
      out.dforce_dproperty(t, kZ + k * prop) = mu * dfn * uz;
    };
    normal_part(kStiffness, c.d_stiffness);
    normal_part(kClearance, -c.d_gap);
    normal_part(kWidth, c.d_width);
    out.dforce_dproperty(t, kTheta + k * kMu) = fn * ut;
    out.dforce_dproperty(t, kZ + k * kMu) = fn * uz;
    auto sliding_part = [&](int prop, double dvt) {
      out.dforce_dproperty(t, kTheta + k * prop) = mu * fn * dut_dvt * dvt;
      out.dforce_dproperty(t, kZ + k * prop) = mu * fn * duz_dvt * dvt;
    };
    sliding_part(kRadius, rotation);
    sliding_part(kEngineOrder, rho * omega);
    sliding_part(kRotationSpeed, rho);
  }
}

}  // namespace hbtrack
