#include "hbtrack/elements/polynomial_elements.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

namespace {

// x^p for a small nonnegative integer p, with 0^0 = 1 (a monomial that omits the dof).
double integer_power(double x, int p) {
  double out = 1.0;
  for (int i = 0; i < p; ++i) out *= x;
  return out;
}

}  // namespace

PolynomialStiffness::PolynomialStiffness(Eigen::MatrixXi exponents) : exponents_(std::move(exponents)) {
  if ((exponents_.array() < 0).any()) throw std::invalid_argument("polynomial_stiffness: exponents must be >= 0");
  for (Eigen::Index m = 0; m < exponents_.rows(); ++m)
    for (Eigen::Index i = 0; i < exponents_.cols(); ++i)
      names_.push_back("coefficients[" + std::to_string(m) + "][" + std::to_string(i) + "]");
}

std::string PolynomialStiffness::configuration() const {
  std::string text = "exponents=" + std::to_string(exponents_.rows()) + "x" + std::to_string(exponents_.cols());
  for (Eigen::Index m = 0; m < exponents_.rows(); ++m)
    for (Eigen::Index i = 0; i < exponents_.cols(); ++i) {
      text += i ? ',' : ';';  // a row per monomial
      text += std::to_string(exponents_(m, i));
    }
  return text;
}

void PolynomialStiffness::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& /*v*/, double /*omega*/,
                                   const std::vector<double>& props, ElementResponse& out, bool want_property_derivatives) const {
  const Eigen::Index n = x.rows();
  const int k = local_dofs();
  const Eigen::Index monomials = exponents_.rows();
  if (exponents_.cols() != k || static_cast<Eigen::Index>(props.size()) != monomials * k)
    throw std::invalid_argument("polynomial_stiffness: exponents/coefficients do not match the element's dofs");
  out.force.setZero(n, k);
  out.dforce_dx.setZero(n, k * k);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  if (want_property_derivatives) out.dforce_dproperty.setZero(n, k * static_cast<Eigen::Index>(props.size()));
  Eigen::VectorXd dz(k);
  for (Eigen::Index t = 0; t < n; ++t) {
    for (Eigen::Index m = 0; m < monomials; ++m) {
      double z = 1.0;
      for (int j = 0; j < k; ++j) z *= integer_power(x(t, j), exponents_(m, j));
      // d z / d x_j by the product rule (no division: x_j may be zero).
      for (int j = 0; j < k; ++j) {
        const int p = exponents_(m, j);
        if (p == 0) {
          dz(j) = 0.0;
          continue;
        }
        double d = p * integer_power(x(t, j), p - 1);
        for (int l = 0; l < k; ++l)
          if (l != j) d *= integer_power(x(t, l), exponents_(m, l));
        dz(j) = d;
      }
      for (int i = 0; i < k; ++i) {
        const double e = props[static_cast<size_t>(m * k + i)];
        out.force(t, i) += e * z;
        for (int j = 0; j < k; ++j) out.dforce_dx(t, i + k * j) += e * dz(j);
        if (want_property_derivatives) out.dforce_dproperty(t, i + k * (m * k + i)) = z;
      }
    }
  }
}

const std::vector<std::string>& PowerDamper::property_names() const {
  static const std::vector<std::string> names{"coefficient", "exponent"};
  return names;
}

ScalarElement::ScalarLaw PowerDamper::law(double, double d_dot, const double* p) const {
  const double c = p[0], e = p[1];
  const double a = std::abs(d_dot);
  const double s = d_dot > 0 ? 1.0 : (d_dot < 0 ? -1.0 : 0.0);
  ScalarLaw out;
  const double power = std::pow(a, e);
  out.f = c * power * s;
  // d/dv |v|^e sign(v) = e |v|^(e-1); at v = 0 it is 1 for e = 1 and 0 for e > 1.
  out.df_dv = a > 0 ? c * e * std::pow(a, e - 1.0) : (e == 1.0 ? c : 0.0);
  out.df_dp[0] = power * s;
  out.df_dp[1] = a > 0 ? c * power * std::log(a) * s : 0.0;
  return out;
}

}  // namespace hbtrack
