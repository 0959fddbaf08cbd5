#pragma once
// Smooth pointwise laws of NLvib's library: a polynomial stiffness in several dofs and a
// power-law damper along one scalar coordinate.
#include <Eigen/Dense>

#include "hbtrack/elements/scalar_elements.hpp"

namespace hbtrack {

// NLvib's polynomialStiffness on the element's own dofs x_1..x_k:
//   z_m = prod_j x_j^exponents(m, j),   f_i = sum_m coefficients(m, i) z_m,
// with one row per monomial m (exponents: nonnegative integers, k columns; coefficients: k
// columns, one per force component). Each coefficient is a property named
// "coefficients[m][i]" so it can be bound to a parameter and tracked.
class PolynomialStiffness final : public NonlinearElement {
 public:
  // exponents: M x k. Builds the M*k property names (bindings are set by the caller).
  explicit PolynomialStiffness(Eigen::MatrixXi exponents);
  std::string type() const override { return "polynomial_stiffness"; }
  const std::vector<std::string>& property_names() const override { return names_; }
  bool depends_on_velocity() const override { return false; }
  void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                ElementResponse& out, bool want_property_derivatives) const override;
  const Eigen::MatrixXi& exponents() const { return exponents_; }
  std::string configuration() const override;

 private:
  Eigen::MatrixXi exponents_;
  std::vector<std::string> names_;
};

// f = coefficient |d'|^exponent sign(d') along d = w^T x (exponent >= 1): exponent 1 is a
// linear dashpot, 2 NLvib's quadraticDamper, 3 a cubic damper.
// Properties: coefficient, exponent.
class PowerDamper final : public ScalarElement {
 public:
  std::string type() const override { return "power_damper"; }
  const std::vector<std::string>& property_names() const override;
  bool depends_on_velocity() const override { return true; }
  std::string smoothness_limit() const override {
    return "|v|^p sign(v) has a discontinuous second derivative at v = 0 when 1 < p < 3 (e.g. the quadratic damper)";
  }

 protected:
  ScalarLaw law(double, double d_dot, const double* p) const override;
};

}  // namespace hbtrack
