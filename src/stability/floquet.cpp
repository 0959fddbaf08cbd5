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

namespace {
// Hill's truncation splits a real pair by ~1e-4 in its imaginary part.
bool is_real(std::complex<double> mu) { return std::abs(mu.imag()) <= 1e-3 * std::abs(mu); }

// (-1)^(crossings outside the circle) * (distance of the nearest candidate to the circle): its
// sign flips exactly when a candidate crosses the circle, and multipliers deep inside (which a
// partial eigensolver may or may not return) do not change it.
template <class Candidate>
double signed_circle_distance(const Eigen::VectorXcd& mu, Candidate candidate, int per_crossing) {
  int outside = 0;
  double nearest = 1.0;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    if (!candidate(mu(i))) continue;
    const double modulus = std::abs(mu(i));
    if (modulus > 1.0) ++outside;
    nearest = std::min(nearest, std::abs(modulus - 1.0));
  }
  return ((outside / per_crossing) % 2 ? -1.0 : 1.0) * nearest;
}
}  // namespace

double period_doubling_test(const Eigen::VectorXcd& mu) {
  return signed_circle_distance(
      mu, [](std::complex<double> m) { return is_real(m) && m.real() < 0; }, 1);
}

double neimark_sacker_test(const Eigen::VectorXcd& mu) {
  // Complex multipliers cross in conjugate pairs. A collision of two real multipliers outside
  // the circle into a complex pair also flips it: a located NS point is confirmed below.
  return signed_circle_distance(
      mu, [](std::complex<double> m) { return !is_real(m); }, 2);
}

std::optional<SpecialPointType> crossing_type(const Eigen::VectorXcd& mu, double tolerance, double real_tolerance) {
  // The multiplier nearest the circle among those within `tolerance` of it decides; a real one
  // (or a nearly real pair) at -1 is a period doubling even when the NS test function flipped.
  double nearest = tolerance;
  std::optional<SpecialPointType> type;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    const double distance = std::abs(std::abs(mu(i)) - 1.0);
    if (distance > nearest) continue;
    const bool real = std::abs(mu(i).imag()) <= real_tolerance * std::abs(mu(i));
    nearest = distance;
    type = !real ? SpecialPointType::neimark_sacker : mu(i).real() < 0 ? SpecialPointType::period_doubling : SpecialPointType::limit_point;
  }
  return type;
}

bool has_multiplier_on_unit_circle(const Eigen::VectorXcd& mu, SpecialPointType type, double tolerance) {
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    if (type == SpecialPointType::period_doubling && std::abs(mu(i) + 1.0) <= tolerance) return true;
    if (type == SpecialPointType::limit_point && std::abs(mu(i) - 1.0) <= tolerance) return true;
    if (type == SpecialPointType::neimark_sacker && !is_real(mu(i)) && std::abs(std::abs(mu(i)) - 1.0) <= tolerance) return true;
  }
  return false;
}

}  // namespace hbtrack
