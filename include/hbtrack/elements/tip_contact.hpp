#pragma once
// The blade-tip/casing contact node of the paper (section 4.2): three local dofs
// [radial, circumferential, axial] of one tip node, a rigid cylindrical casing at `clearance`,
// a regularised normal law, and permanent-sliding dry friction (eqs 47-48):
//   f_theta = mu f_N (v_theta + rho W) / |V|,  f_z = mu f_N v_z / |V|,
//   |V| = sqrt((v_theta + rho W)^2 + v_z^2),   W = engine_order * omega + rotation_speed.
// Properties: stiffness, clearance, width, mu, radius, engine_order, rotation_speed.
#include "hbtrack/elements/contact_laws.hpp"
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

class TipContact final : public NonlinearElement {
 public:
  explicit TipContact(ContactLawKind kind = ContactLawKind::polynomial) : kind_(kind) {}
  std::string type() const override { return "tip_contact"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return true; }
  bool depends_on_omega() const override { return true; }
  std::string smoothness_limit() const override { return hbtrack::smoothness_limit(kind_); }
  // The penalty law's corner: the radial displacement at the clearance.
  int switching_surfaces(const std::vector<double>& property_values) const override;
  void switching_values(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, const std::vector<double>& property_values,
                        double* out) const override;
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega,
                const std::vector<double>& property_values, ElementResponse& out,
                bool want_property_derivatives) const override;
  ContactLawKind law_kind() const { return kind_; }

 private:
  ContactLawKind kind_;
};

}  // namespace hbtrack
