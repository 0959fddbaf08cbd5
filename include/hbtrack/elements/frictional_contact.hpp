#pragma once
// Point contact with a varying normal load and elastic dry friction (a Jenkins element whose
// slip limit is mu N(t)), with separation. Two dofs: [normal, tangential].
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
class FrictionalContact final : public NonlinearElement {
 public:
  std::string type() const override { return "frictional_contact"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }
  bool history_dependent() const override { return true; }
  std::string smoothness_limit() const override {
    return "contact separation and stick-slip transitions make the force non-smooth";
  }
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega,
                const std::vector<double>& property_values, ElementResponse& out,
                bool want_property_derivatives) const override;
  // One internal variable: the slider position z (T = k_t (x_t - z)).
  int history_state_size() const override { return 1; }
  void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                    const std::vector<double>& property_values, HistoryStep& out) const override;
  Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega,
                                   const std::vector<double>& property_values) const override;
};

}  // namespace hbtrack
