#pragma once
// The four-parameter Iwan model of Segalman (J. Appl. Mech. 72, 2005) for bolted lap joints,
// along d = w^T x: a parallel array of Jenkins sliders (unit-stiffness springs in series with
// slip lengths phi) whose density is
//   rho(phi) = R phi^chi on 0 < phi < phi_max,  plus S delta(phi - phi_max),
// so that f = integral of rho(phi) (d - z(phi)) over phi with |d - z(phi)| <= phi. Properties:
//   limit_force F_S  force at which the whole joint slips (macro-slip),
//   stiffness   K_T  tangent stiffness of the stuck joint,
//   chi              power-law exponent (> -1): the micro-slip dissipation per cycle grows as
//                    amplitude^(3 + chi),
//   beta             share of the Dirac at phi_max: S = K_T beta / (1 + beta) (>= 0),
// from which phi_max = F_S (1 + beta) / (K_T (beta + (chi + 1)/(chi + 2))) and
// R = K_T (chi + 1) / ((1 + beta) phi_max^(chi + 1)).
// Discretisation: `sliders` sliders for the power-law part, one per interval of a geometric grid
// s_i = phi_i / phi_max = 10^(-5 (n - i)/(n - 1)) (i = 1..n, s_0 = 0: five decades below
// phi_max), each with the interval's exact stiffness integral of rho and slip force integral
// of phi rho, so that the stuck stiffness K_T and the macro-slip force F_S are exact; plus the
// Dirac slider. The micro-slip dissipation of the discrete array is second order in the grid
// ratio (docs/elements.md has the convergence study behind the default of 50 sliders).
// Each slider is a Jenkins element with its exact periodic stick-slip (elastic_dry_friction).
#include "hbtrack/elements/scalar_elements.hpp"

namespace hbtrack {

class Iwan final : public ScalarElement {
 public:
  static constexpr int kDefaultSliders = 50;
  static constexpr double kDecades = 5.0;  // span of the geometric grid below phi_max

  explicit Iwan(int sliders = kDefaultSliders);
  std::string type() const override { return "iwan"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }
  bool history_dependent() const override { return true; }
  std::string smoothness_limit() const override { return "stick-slip transitions of its sliders make the Iwan force non-smooth"; }
  bool force_has_corners() const override { return true; }
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;
  // One internal variable per slider (the power-law sliders, then the Dirac one): its position.
  int history_state_size() const override { return sliders_ + 1; }
  void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                    const std::vector<double>& property_values, HistoryStep& out) const override;
  Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& property_values) const override;

  int sliders() const { return sliders_; }
  std::string configuration() const override { return ScalarElement::configuration() + ";sliders=" + std::to_string(sliders_); }
  // The discrete array: stiffness k_i and slip force F_i of each slider (power-law sliders, then
  // the Dirac one), with their derivatives with respect to the four properties (columns).
  struct SliderArray {
    Eigen::VectorXd stiffness, limit;
    Eigen::MatrixXd dstiffness, dlimit;  // (sliders + 1) x 4
    double phi_max = 0;
  };
  SliderArray discretise(const std::vector<double>& property_values) const;

 protected:
  // Not used: the force is not a pointwise function of (d, d').
  ScalarLaw law(double, double, const double*) const override;

 private:
  int sliders_;
  Eigen::VectorXd grid_;  // s_0 = 0 < s_1 < ... < s_n = 1
};

}  // namespace hbtrack
