#pragma once
// The Jenkins element (NLvib's elasticDryFriction): a spring of `stiffness` in series with a
// Coulomb slider of `limit_force`, along d = w^T x. History-dependent: evaluate() returns the
// exact periodic steady state of the slider over the sampled period.
#include "hbtrack/elements/scalar_elements.hpp"

namespace hbtrack {

// Periodic steady state (slider position z, force f = k (d - z), |f| <= F):
//  * When the period's range of d exceeds 2F/k the slider slips, and at the sample where d is
//    largest the force is exactly +F whatever the state before (the slider was pushed there
//    since the minimum). One pass over the period started at that sample is therefore the
//    periodic solution itself; no iteration is needed.
//  * Otherwise the slider never moves and the state is not determined by the motion. We take
//    the slider at the midrange of d, z = (max d + min d) / 2: it is the limit of the slipping
//    solution as the range falls to 2F/k (so the force is continuous across the slip threshold,
//    which the mean of d is not when d has higher harmonics) and equals the mean displacement
//    for a harmonic motion.
// Derivatives: in stick f(t) = k (d(t) - d(a)) + s F with a the last slip sample and s its
// direction, so d f(t) / d d(s) = k (delta_ts - delta_sa); in slip it is zero. Without slip
// the anchor is the midrange: k (delta_ts - (delta_s,argmax + delta_s,argmin) / 2).
// Properties: stiffness, limit_force.
class ElasticDryFriction final : public ScalarElement {
 public:
  std::string type() const override { return "elastic_dry_friction"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }
  bool history_dependent() const override { return true; }
  bool stuck_slider_position_is_free() const override { return true; }
  std::string smoothness_limit() const override { return "stick-slip transitions make the Jenkins force non-smooth"; }
  bool force_has_corners() const override { return true; }
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;
  // One internal variable: the slider position z (f = k (d - z)).
  int history_state_size() const override { return 1; }
  void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                    const std::vector<double>& property_values, HistoryStep& out) const override;
  Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& property_values) const override;

 protected:
  // Not used: the force is not a pointwise function of (d, d').
  ScalarLaw law(double, double, const double*) const override;
};

}  // namespace hbtrack
