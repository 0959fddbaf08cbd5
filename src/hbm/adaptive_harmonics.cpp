#include "hbtrack/hbm/adaptive_harmonics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hbtrack {

namespace {
std::string adaptive_field(const char* key) { return std::string("harmonic_balance.adaptive.") + key; }

// sum over the dofs of a_k^2 + b_k^2 (dense harmonic-major layout: a_k at block 2k-1, b_k at 2k).
double harmonic_energy(const Eigen::VectorXd& x, int dofs, int k) { return x.segment((2 * k - 1) * dofs, 2 * dofs).squaredNorm(); }
}  // namespace

void AdaptiveHarmonics::validate() const {
  if (!enabled()) return;
  // Two harmonics above the first are measured (top_harmonic_share): H - 1 >= 2.
  if (min < 3)
    throw std::invalid_argument(adaptive_field("min") + ": must be >= 3 (the criterion reads harmonics H-1 and H above the first), got " +
                                std::to_string(min));
  if (max < min)
    throw std::invalid_argument(adaptive_field("max") + ": must be >= min = " + std::to_string(min) + ", got " + std::to_string(max));
  if (max > 500) throw std::invalid_argument(adaptive_field("max") + ": must be <= 500, got " + std::to_string(max));
  if (!(drop_below > 0) || !std::isfinite(drop_below))
    throw std::invalid_argument(adaptive_field("drop_below") + ": must be > 0 and finite");
  if (!(add_above < 1) || !std::isfinite(add_above))
    throw std::invalid_argument(adaptive_field("add_above") + ": must be < 1 (a share of the response)");
  if (!(add_above > drop_below))
    throw std::invalid_argument(adaptive_field("add_above") + ": must be > drop_below (the band between them keeps H from chattering)");
}

double top_harmonic_share(const Eigen::VectorXd& x, int dofs, int upto) {
  double total = 0, top = 0;
  for (int k = 1; k <= upto; ++k) {
    const double e = harmonic_energy(x, dofs, k);
    total += e;
    if (k >= 2 && k >= upto - 1) top += e;
  }
  return total > 0 ? std::sqrt(top / total) : 0.0;
}

int next_harmonic_count(const AdaptiveHarmonics& a, const Eigen::VectorXd& x, int dofs, int harmonics) {
  if (harmonics < a.max && top_harmonic_share(x, dofs, harmonics) > a.add_above) return harmonics + 1;
  const double middle = std::sqrt(a.add_above * a.drop_below);
  int h = harmonics;
  while (h > a.min && top_harmonic_share(x, dofs, h) < a.drop_below && top_harmonic_share(x, dofs, h - 1) < middle) --h;
  return std::clamp(h, a.min, a.max);
}

Eigen::VectorXd with_harmonic_count(const Eigen::VectorXd& x, int dofs, int to) {
  const Eigen::Index size = static_cast<Eigen::Index>(dofs) * (2 * to + 1);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(size);
  const Eigen::Index kept = std::min(size, x.size());
  out.head(kept) = x.head(kept);
  return out;
}

}  // namespace hbtrack
