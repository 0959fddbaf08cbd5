#pragma once
// Harmonics chosen as a branch is followed (case file `[harmonic_balance] adaptive`): the
// harmonic count H rises where the top harmonics carry a noticeable share of the response and
// falls where they carry almost none. The settings and the criterion; analysis/adaptive_nfrc.hpp
// follows a branch with it.
#include <Eigen/Dense>

namespace hbtrack {

struct AdaptiveHarmonics {
  int min = 0, max = 0;      // the bounds of H; max = 0: off, H stays the case's
  double add_above = 1e-4;   // raise H while the top share is above this
  double drop_below = 1e-6;  // lower H where it is below this
  bool enabled() const { return max > 0; }
  // Throws std::invalid_argument naming the field (harmonic_balance.adaptive.KEY) and the rule.
  void validate() const;
};

// The share of the top two harmonics H-1 and H in the response of the q dofs of x (harmonic-major
// coefficients in the dense layout 0..H), taken up to harmonic `upto` <= H:
//   sqrt(|X_{upto-1}|^2 + |X_upto|^2) / sqrt(sum_{k=1..upto} |X_k|^2),  |X_k|^2 = sum_dofs a_k^2 + b_k^2.
// Two harmonics, not one: a symmetric law leaves every other harmonic zero, and the top one
// alone would then read zero at every even H. 0 for a response without harmonics >= 1.
double top_harmonic_share(const Eigen::VectorXd& x, int dofs, int upto);

// The harmonic count the point x (balanced with H harmonics) asks for: H + 1 when the top share
// is above add_above (the caller solves the point again there and asks again), fewer when it is
// below drop_below and the share of the truncated response stays below the middle of the band
// (sqrt(add_above drop_below)), so that it does not ask to rise again at once; within [min, max].
int next_harmonic_count(const AdaptiveHarmonics& a, const Eigen::VectorXd& x, int dofs, int harmonics);

// x (dense layout 0..from, q dofs) with harmonics 0..to: padded with zeros or truncated.
Eigen::VectorXd with_harmonic_count(const Eigen::VectorXd& x, int dofs, int to);

}  // namespace hbtrack
