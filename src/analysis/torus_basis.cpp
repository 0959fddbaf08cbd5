#include "hbtrack/analysis/torus_basis.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbtrack {

TorusBasis::TorusBasis(int h1, int h2, int n1, int n2) : h1_(h1), h2_(h2), n1_(n1), n2_(n2) {
  if (h1 < 1 || h2 < 1)
    throw std::invalid_argument("torus harmonics must be H1 >= 1 and H2 >= 1, got " + std::to_string(h1) + "," + std::to_string(h2));
  if (n1 < 2 * h1 + 1 || n2 < 2 * h2 + 1)
    throw std::invalid_argument("torus samples must be N1 >= 2 H1 + 1 = " + std::to_string(2 * h1 + 1) + " and N2 >= 2 H2 + 1 = " +
                                std::to_string(2 * h2 + 1) + ", got " + std::to_string(n1) + "," + std::to_string(n2));
  pairs_.emplace_back(0, 0);
  for (int k2 = 1; k2 <= h2; ++k2) pairs_.emplace_back(0, k2);
  for (int k1 = 1; k1 <= h1; ++k1)
    for (int k2 = -h2; k2 <= h2; ++k2) pairs_.emplace_back(k1, k2);
  const int nc = coefficients(), g_count = grid();
  synthesis_.resize(g_count, nc);
  d1_.resize(g_count, nc);
  d2_.resize(g_count, nc);
  analysis_.resize(nc, g_count);
  for (int g = 0; g < g_count; ++g) {
    const double t1 = theta1(g), t2 = theta2(g);
    synthesis_(g, 0) = 1.0;
    d1_(g, 0) = d2_(g, 0) = 0.0;
    analysis_(0, g) = 1.0 / g_count;
    for (int p = 1; p < pairs(); ++p) {
      const auto [k1, k2] = pair(p);
      const double phase = k1 * t1 + k2 * t2, c = std::cos(phase), s = std::sin(phase);
      synthesis_(g, cosine(p)) = c;
      synthesis_(g, sine(p)) = s;
      d1_(g, cosine(p)) = -k1 * s;
      d1_(g, sine(p)) = k1 * c;
      d2_(g, cosine(p)) = -k2 * s;
      d2_(g, sine(p)) = k2 * c;
      analysis_(cosine(p), g) = 2.0 * c / g_count;
      analysis_(sine(p), g) = 2.0 * s / g_count;
    }
  }
}

double TorusBasis::theta1(int g) const { return 2.0 * std::numbers::pi * (g % n1_) / n1_; }
double TorusBasis::theta2(int g) const { return 2.0 * std::numbers::pi * (g / n1_) / n2_; }

int TorusBasis::find_pair(int k1, int k2, int* sign) const {
  for (int flip : {1, -1})
    for (int p = 0; p < pairs(); ++p)
      if (pairs_[static_cast<size_t>(p)] == std::pair{flip * k1, flip * k2}) {
        if (sign) *sign = flip;
        return p;
      }
  return -1;
}

}  // namespace hbtrack
