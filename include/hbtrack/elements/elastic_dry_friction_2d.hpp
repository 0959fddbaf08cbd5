#pragma once
// A Jenkins element whose slider slips in a plane: a spring of `stiffness` k in series with a
// Coulomb slider of `limit_force` F (a constant mu N) in two tangential directions,
//   u = W x  (2 x k weights W: two directions over the element's dofs),
//   T = k (u - z),  |T| <= F,  z moving only along T (the slider point z in the plane).
// The law is the return mapping (radial projection) of src/elements/coulomb_slider.hpp, sample
// by sample: trial T* = k (u_t - z_(t-1)); stick if |T*| <= F, else T = F T*/|T*|, z = u - T/k.
// The force on the element's dofs is W^T T.
// Periodic steady state over the sampled period: Newton on the slider position at the period's
// start (a pass is affine in it at a fixed stick-slip pattern) until it repeats to round-off; a
// slider that can stick all period is put at the position of largest margin (the centre of the
// smallest circle around the motion, continuous with the slipping state). Motion along one
// direction only is elastic_dry_friction along it. Sensitivities: the slider's linear periodic
// recurrence as an operator (history_operator), exact for the sampled law.
// Properties: stiffness, limit_force.
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

class ElasticDryFriction2D final : public NonlinearElement {
 public:
  std::string type() const override { return "elastic_dry_friction_2d"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }
  bool history_dependent() const override { return true; }
  bool stuck_slider_position_is_free() const override { return true; }
  std::string smoothness_limit() const override { return "stick-slip transitions make the Jenkins force non-smooth"; }
  bool force_has_corners() const override { return true; }
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;
  // Two internal variables: the slider position z in the plane of u.
  int history_state_size() const override { return 2; }
  void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                    const std::vector<double>& property_values, HistoryStep& out) const override;
  Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& property_values) const override;
  std::string configuration() const override {
    return "weights=" + exact_text(weights.row(0).transpose()) + ";" + exact_text(weights.row(1).transpose());
  }

  // u = weights x_local (2 x k). Default: the identity on two dofs [x, y] (grounded), and
  // [[1, 0, -1, 0], [0, 1, 0, -1]] on four [x_a, y_a, x_b, y_b] (between two nodes).
  Eigen::MatrixXd weights;
};

}  // namespace hbtrack
