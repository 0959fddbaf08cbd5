#include "hbtrack/stability/floquet.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace hbtrack {

void finish_floquet(FloquetResult& r, double omega, double tolerance) {
  const double period = 2.0 * std::numbers::pi / omega;
  r.multipliers = (r.exponents * period).array().exp();
  r.max_real = r.exponents.size() ? r.exponents.real().maxCoeff() : -INFINITY;
  r.stable = r.max_real <= tolerance;
}

double period_doubling_test(const Eigen::VectorXcd& mu) {
  std::complex<double> p = 1.0;
  for (Eigen::Index i = 0; i < mu.size(); ++i) p *= 1.0 + mu(i);
  return p.real();  // conjugate pairs make the product real
}

double neimark_sacker_test(const Eigen::VectorXcd& mu) {
  // Only complex multipliers: a real pair with mu_i mu_j = 1 is a neutral saddle, not a
  // bifurcation. Scaled factors keep the product within range for many multipliers.
  std::complex<double> p = 1.0;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    if (std::abs(mu(i).imag()) <= 1e-9 * std::abs(mu(i))) continue;
    for (Eigen::Index j = i + 1; j < mu.size(); ++j) {
      if (std::abs(mu(j).imag()) <= 1e-9 * std::abs(mu(j))) continue;
      const std::complex<double> f = mu(i) * mu(j) - 1.0;
      p *= f / std::max(1.0, std::abs(f));
    }
  }
  return p.real();
}

}  // namespace hbtrack
