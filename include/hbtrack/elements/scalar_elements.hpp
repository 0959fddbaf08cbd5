#pragma once
// Elements that act along one scalar coordinate d = w^T x (a dof, or a relative displacement
// between dofs) and return the force w f(d, d') on their dofs.
#include "hbtrack/elements/contact_laws.hpp"
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

class ScalarElement : public NonlinearElement {
 public:
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega,
                const std::vector<double>& property_values, ElementResponse& out,
                bool want_property_derivatives) const override;

  // d = weights^T x_local. Default: [1] on one dof, [1, -1] between two dofs.
  Eigen::VectorXd weights;

 protected:
  struct ScalarLaw {
    double f = 0, df_dd = 0, df_dv = 0;
    double df_dp[4] = {0, 0, 0, 0};
  };
  virtual ScalarLaw law(double d, double d_dot, const double* properties) const = 0;
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
  explicit GapContact(ContactLawKind kind, std::string type_name)
      : kind_(kind), type_name_(std::move(type_name)) {}
  std::string type() const override { return type_name_; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return false; }
  std::string smoothness_limit() const override { return hbtrack::smoothness_limit(kind_); }
  ContactLawKind law_kind() const { return kind_; }

 protected:
  ScalarLaw law(double d, double, const double* p) const override;

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
