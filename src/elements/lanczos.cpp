#include "hbtrack/elements/lanczos.hpp"

#include <cmath>
#include <numbers>

namespace hbtrack {

Eigen::VectorXd lanczos_factors(int harmonics, double exponent) {
  Eigen::VectorXd sigma = Eigen::VectorXd::Ones(2 * harmonics + 1);
  if (exponent == 0.0) return sigma;
  for (int j = 1; j <= harmonics; ++j) {
    const double x = std::numbers::pi * j / (harmonics + 1.0);
    const double s = std::pow(std::sin(x) / x, exponent);
    sigma(2 * j - 1) = s;
    sigma(2 * j) = s;
  }
  return sigma;
}

}  // namespace hbtrack
