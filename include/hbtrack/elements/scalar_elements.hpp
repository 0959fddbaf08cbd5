#pragma once
// Elements that act along one scalar coordinate d = w^T x (a dof, or a relative displacement
// between dofs) and return the force w f(d, d') on their dofs.
#include "hbtrack/elements/contact_laws.hpp"
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

class ScalarElement : public NonlinearElement {
 public:
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;

  // d = weights^T x_local. Default: [1] on one dof, [1, -1] between two dofs.
  Eigen::VectorXd weights;
  std::string configuration() const override { return "weights=" + exact_text(weights); }

 protected:
  struct ScalarLaw {
    double f = 0, df_dd = 0, df_dv = 0;
    double df_dp[4] = {0, 0, 0, 0};
  };
  virtual ScalarLaw law(double d, double d_dot, const double* properties) const = 0;
  // Over a period of N samples (the AFT), a law with a corner is replaced by its mean over one
  // sample's width, the displacement taken linear across it: with h = (pi / N) dd/dtau,
  //   f(d, h) = (F(d + h) - F(d - h)) / 2h,  F' = the law.
  // The sampled force then changes smoothly (C1) as a sample enters contact, instead of with the
  // jump of tangent that makes the branch a saw-tooth of folds narrower than a sample. It tends
  // to the law as N grows (the error is O(1/N^2), that of sampling itself) and is the law itself
  // at a turning point (h = 0). df_dv is d f / d h here. False: the law has no corner.
  virtual bool sample_mean_law(double /*d*/, double /*h*/, const double* /*properties*/, ScalarLaw& /*out*/) const { return false; }
  virtual bool averages_over_samples(const std::vector<double>& /*properties*/) const { return false; }
};

// f = k3 d^3. Properties: cubic_stiffness.
class CubicSpring final : public ScalarElement {
 public:
  std::string type() const override { return "cubic_spring"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }

 protected:
  ScalarLaw law(double d, double, const double* p) const override;
};

// Normal contact along d with an initial gap: f = f_N(d - gap) for the chosen law.
// `unilateral_spring` is the penalty law; `regularized_contact` defaults to the polynomial law.
// Properties: stiffness, gap, width.
class GapContact final : public ScalarElement {
 public:
  explicit GapContact(ContactLawKind kind, std::string type_name) : kind_(kind), type_name_(std::move(type_name)) {}
  std::string type() const override { return type_name_; }
  const std::vector<std::string>& property_names() const override;
  // The penalty law's sample mean (sample_mean_law) depends on the velocity.
  bool depends_on_velocity() const override { return kind_ == ContactLawKind::penalty; }
  std::string smoothness_limit() const override { return hbtrack::smoothness_limit(kind_); }
  bool force_has_corners() const override { return kind_ == ContactLawKind::penalty; }
  // The penalty law's corner d = gap (also the polynomial law given no width).
  int switching_surfaces(const std::vector<double>& property_values) const override;
  void switching_values(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, const std::vector<double>& property_values,
                        double* out) const override;
  ContactLawKind law_kind() const { return kind_; }
  std::string configuration() const override { return ScalarElement::configuration() + ";law=" + to_string(kind_); }

 protected:
  ScalarLaw law(double d, double, const double* p) const override;
  bool sample_mean_law(double d, double h, const double* p, ScalarLaw& out) const override;
  bool averages_over_samples(const std::vector<double>& property_values) const override { return switching_surfaces(property_values) > 0; }

 private:
  ContactLawKind kind_;
  std::string type_name_;
};

// Regularised Coulomb friction under a constant normal load:
// f = mu * normal_load * tanh(d' / regularization_velocity).
// Properties: mu, normal_load, regularization_velocity.
class TanhFriction final : public ScalarElement {
 public:
  std::string type() const override { return "tanh_friction"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return true; }

 protected:
  ScalarLaw law(double, double d_dot, const double* p) const override;
};

}  // namespace hbtrack
