#pragma once
// Two-frequency (hyper-time) Fourier basis of a quasi-periodic response on a 2-torus:
//   x(theta1, theta2) = A_00 + sum_p [a_p cos(k1 theta1 + k2 theta2) + b_p sin(k1 theta1 + k2 theta2)],
// theta1 = omega t (the forcing's phase), theta2 = omega2 t (the second base frequency, the
// Neimark-Sacker frequency where the torus is born). The pairs p = (k1, k2) are those of the box
// |k1| <= H1, |k2| <= H2 taken once each: (0, 0), then (0, k2) for 1 <= k2 <= H2, then (k1, k2)
// for 1 <= k1 <= H1 and -H2 <= k2 <= H2 (a pair and its opposite are one real harmonic).
// Coefficient index: 0 is A_00 (the mean itself, no factor 1/2), 2p - 1 is a_p, 2p is b_p.
// The torus is sampled on the N1 x N2 grid theta1_i = 2 pi i / N1, theta2_j = 2 pi j / N2
// (sample g = i + N1 j); with N1 > 2 H1 and N2 > 2 H2 the analysis matrix is the exact inverse of
// the synthesis on the harmonics kept (the 2-D DFT, as a dense matrix: the small systems this is for).
#include <Eigen/Dense>
#include <utility>
#include <vector>

namespace hbtrack {

class TorusBasis {
 public:
  // Throws std::invalid_argument unless H1 >= 1, H2 >= 1, N1 >= 2 H1 + 1, N2 >= 2 H2 + 1.
  TorusBasis(int h1, int h2, int n1, int n2);

  int h1() const { return h1_; }
  int h2() const { return h2_; }
  int n1() const { return n1_; }
  int n2() const { return n2_; }
  int grid() const { return n1_ * n2_; }
  int pairs() const { return static_cast<int>(pairs_.size()); }
  int coefficients() const { return 2 * pairs() - 1; }
  // The pair (k1, k2) of pair index p (p = 0 the mean).
  const std::pair<int, int>& pair(int p) const { return pairs_[static_cast<size_t>(p)]; }
  // Pair index of (k1, k2) or of (-k1, -k2), whichever is kept; -1 outside the box. `sign` (if
  // given) is -1 when the opposite was found (its sine coefficient then changes sign).
  int find_pair(int k1, int k2, int* sign = nullptr) const;
  // Coefficient indices of pair p: cosine and sine (p >= 1).
  static int cosine(int p) { return 2 * p - 1; }
  static int sine(int p) { return 2 * p; }
  // The pair of coefficient c (c = 0 the mean).
  int pair_of(int c) const { return (c + 1) / 2; }
  // Angular frequency k1 omega + k2 omega2 of coefficient c.
  double frequency(int c, double omega, double omega2) const {
    const auto& [k1, k2] = pair(pair_of(c));
    return k1 * omega + k2 * omega2;
  }

  // E: grid x coefficients, samples = E * coefficients; E1, E2: samples of d/d(theta1) and
  // d/d(theta2) (the velocity is omega E1 + omega2 E2 times the coefficients); P: coefficients x
  // grid, the projection back (P E = I).
  const Eigen::MatrixXd& synthesis() const { return synthesis_; }
  const Eigen::MatrixXd& theta1_derivative() const { return d1_; }
  const Eigen::MatrixXd& theta2_derivative() const { return d2_; }
  const Eigen::MatrixXd& analysis() const { return analysis_; }
  double theta1(int g) const;
  double theta2(int g) const;

 private:
  int h1_, h2_, n1_, n2_;
  std::vector<std::pair<int, int>> pairs_;
  Eigen::MatrixXd synthesis_, d1_, d2_, analysis_;
};

}  // namespace hbtrack
