#pragma once
// Point contact with a varying normal load and elastic dry friction (a Jenkins element whose
// slip limit is mu N(t)), with separation. Two dofs: [normal, tangential]; or, as
// frictional_contact_2d (penalty only), three: [normal, tangential_1, tangential_2], the slider
// slipping in the tangential plane (the Coulomb disc |T| <= mu N(t) of coulomb_slider.hpp).
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

// Normal: N(t) = max(0, normal_preload + normal_stiffness x_n(t)) (penalty; a negative preload is
// an initial gap of -preload / normal_stiffness). Tangential: T = tangential_stiffness (x_t - z)
// with |T| <= mu N; z follows x_t while separated (T = 0): the one-direction case of the slider
// in src/elements/coulomb_slider.hpp, shared with tip_contact's stick-slip friction.
// Periodic steady state: every slip or separation sample erases the memory, so the pass after
// the first event is periodic (the second pass in the tests' motions). A period without any
// event is a permanent stick, with z at the midrange of x_t as for elastic_dry_friction.
// Sensitivities: an operator (history_operator), the slider's periodic recurrence.
// Properties: normal_stiffness, tangential_stiffness, mu, normal_preload.
enum class ContactFormulation { penalty, dlft };
ContactFormulation parse_contact_formulation(const std::string& name);  // throws std::invalid_argument

// law = "dlft": the dynamic Lagrangian frequency/time method (Nacivet, Pierre, Thouverez &
// Jezequel, JSV 265, 2003; pyHarm's law "dlft"), a rigid contact and rigid-stick Coulomb friction
// whose forces are Lagrange multipliers of the harmonic balance. The prediction
//   lambda = epsilon (x - (gap, 0)) - r_lin,  r_lin the linear residual at the dofs
// (NonlinearElement::uses_linear_residual), is corrected in time: N = max(lambda_n, 0), and the
// tangential force a stick prediction from the last position, bounded by mu N; in equations,
// the penalty law above with k_n = k_t = epsilon applied to lambda / epsilon. At a solution the
// residual at the dofs is epsilon (x - X), X the displacement the contact law allows, so the
// contact holds exactly (x_n = gap in contact, x_t constant in stick) whatever epsilon > 0,
// which only affects Newton's path. Properties: mu, epsilon, gap (the contact plane: x_n <= gap).
class FrictionalContact final : public NonlinearElement {
 public:
  // directions: 1, or 2 tangential directions (penalty only: frictional_contact_2d).
  explicit FrictionalContact(ContactFormulation law = ContactFormulation::penalty, int directions = 1);
  std::string type() const override { return directions_ == 2 ? "frictional_contact_2d" : "frictional_contact"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }
  bool history_dependent() const override { return true; }
  std::string smoothness_limit() const override { return "contact separation and stick-slip transitions make the force non-smooth"; }
  bool force_has_corners() const override { return true; }
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;
  bool uses_linear_residual() const override { return law_ == ContactFormulation::dlft; }
  void evaluate_with_residual(const Eigen::MatrixXd& x, const Eigen::MatrixXd& r, double omega, const std::vector<double>& property_values,
                              ElementResponse& out, bool want_property_derivatives) const override;
  // Penalty: the slider position z, one variable per tangential direction (T = k_t (x_t - z)).
  // DLFT has no time-domain form.
  int history_state_size() const override { return law_ == ContactFormulation::penalty ? directions_ : 0; }
  void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                    const std::vector<double>& property_values, HistoryStep& out) const override;
  Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& property_values) const override;
  // The slider may slip either way (sense 0); DLFT's contact is rigid (stiffness 0). None in two
  // directions (the coupling names one tangential direction).
  std::optional<FrictionCoupling> friction_coupling(const std::vector<double>& property_values, double omega) const override;
  ContactFormulation law() const { return law_; }
  std::string configuration() const override { return law_ == ContactFormulation::dlft ? "law=dlft" : "law=penalty"; }

 private:
  ContactFormulation law_;
  int directions_;
};

}  // namespace hbtrack
