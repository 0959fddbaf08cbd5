#pragma once
// The blade-tip/casing contact node of the paper (section 4.2): three local dofs
// [radial, circumferential, axial] of one tip node, a rigid cylindrical casing at `clearance`,
// a regularised normal law f_N, and dry friction. The casing turns at the rotation speed
// W = engine_order * omega + rotation_speed, so the tip slides over it at (v_theta + rho W, v_z).
//  * friction = sliding (the paper's eqs 47-48, the default): permanent sliding,
//      f_theta = mu f_N (v_theta + rho W) / |V|,  f_z = mu f_N v_z / |V|,
//      |V| = sqrt((v_theta + rho W)^2 + v_z^2).
//  * friction = stick_slip: a Jenkins slider of `tangential_stiffness` k_t in the two tangential
//    directions (a Coulomb disc |T| <= mu f_N, src/elements/coulomb_slider.hpp) that the casing
//    carries along while it sticks, free when f_N = 0. A history element: its periodic steady
//    state over the sampled period, and an operator for its sensitivities (the memory of the
//    force's direction fades through slip rather than ending). As k_t grows with the casing
//    sliding fast it tends to the sliding law; without rotation the tip can stick.
// Properties: stiffness, clearance, width, mu, radius, engine_order, rotation_speed
// (+ tangential_stiffness with stick_slip).
#include "hbtrack/elements/contact_laws.hpp"
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

enum class TipFriction { sliding, stick_slip };
TipFriction parse_tip_friction(const std::string& name);  // throws std::invalid_argument
std::string to_string(TipFriction friction);

class TipContact final : public NonlinearElement {
 public:
  explicit TipContact(ContactLawKind kind = ContactLawKind::polynomial, TipFriction friction = TipFriction::sliding)
      : kind_(kind), friction_(friction) {}
  std::string type() const override { return "tip_contact"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return friction_ == TipFriction::sliding; }
  bool depends_on_omega() const override { return true; }
  bool history_dependent() const override { return friction_ == TipFriction::stick_slip; }
  std::string smoothness_limit() const override;
  // The penalty law's gap; the stick-slip slider's transitions.
  bool force_has_corners() const override;
  // The penalty law's corner: the radial displacement at the clearance.
  int switching_surfaces(const std::vector<double>& property_values) const override;
  void switching_values(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, const std::vector<double>& property_values,
                        double* out) const override;
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;
  // stick_slip: two internal variables, the slider's position (theta, z) in the tip's frame.
  int history_state_size() const override { return friction_ == TipFriction::stick_slip ? 2 : 0; }
  void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                    const std::vector<double>& property_values, HistoryStep& out) const override;
  Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& property_values) const override;
  // Friction on the tip along -sign(W) theta (the casing drags it the way it turns).
  std::optional<FrictionCoupling> friction_coupling(const std::vector<double>& property_values, double omega) const override;
  ContactLawKind law_kind() const { return kind_; }
  TipFriction friction() const { return friction_; }
  std::string configuration() const override { return "law=" + to_string(kind_) + ";friction=" + to_string(friction_); }

 private:
  void evaluate_sliding(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& p,
                        ElementResponse& out, bool want_property_derivatives) const;
  void evaluate_stick_slip(const Eigen::MatrixXd& x, double omega, const std::vector<double>& p, ElementResponse& out,
                           bool want_property_derivatives) const;

  ContactLawKind kind_;
  TipFriction friction_;
};

}  // namespace hbtrack
