#include "hbtrack/timeint/period_summary.hpp"

#include <cmath>
#include <stdexcept>

#include "hbtrack/hbm/fourier_basis.hpp"

namespace hbtrack {

namespace {

// Extreme value of the parabola through three consecutive samples centred on an extreme sample
// (sign = +1 for a maximum, -1 for a minimum); the sample itself when the vertex lies outside.
double refined_extreme(double before, double at, double after, double sign) {
  const double curvature = before - 2.0 * at + after;
  if (!(sign * curvature < 0)) return at;  // flat or kinked the wrong way: keep the sample
  const double offset = (before - after) / (2.0 * curvature);
  if (std::abs(offset) > 1.0) return at;
  return at - (after - before) * (after - before) / (8.0 * curvature);
}

}  // namespace

double PeriodSummary::first_harmonic() const { return harmonics.size() >= 3 ? std::hypot(harmonics(1), harmonics(2)) : 0.0; }

PeriodSummary summarise_period(const Eigen::VectorXd& samples, int harmonics) {
  const Eigen::Index n = samples.size();
  if (harmonics < 0 || n < 2 * harmonics + 1) throw std::invalid_argument("summarise_period: needs at least 2H+1 samples per period");
  PeriodSummary s;
  Eigen::Index imax = 0, imin = 0;
  s.max = samples.maxCoeff(&imax);
  s.min = samples.minCoeff(&imin);
  if (n >= 3) {
    auto at = [&](Eigen::Index i) { return samples((i + n) % n); };  // the period wraps around
    s.max = refined_extreme(at(imax - 1), s.max, at(imax + 1), 1.0);
    s.min = refined_extreme(at(imin - 1), s.min, at(imin + 1), -1.0);
  }
  // The HBM basis' own analysis matrix: same coefficient layout and a0 convention.
  const FourierBasis basis(harmonics, static_cast<int>(n));
  s.harmonics = basis.analysis() * samples;
  return s;
}

}  // namespace hbtrack
