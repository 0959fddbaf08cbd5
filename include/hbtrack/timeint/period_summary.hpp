#pragma once
// What one sampled period of a steady-state signal says: its extremes and its Fourier
// coefficients, in the harmonic balance layout (a0 = twice the mean, then a_j, b_j), so that a
// simulated period compares directly with an HBM solution.
#include <Eigen/Dense>

namespace hbtrack {

struct PeriodSummary {
  double max = 0, min = 0;
  Eigen::VectorXd harmonics;      // [a0, a1, b1, ..., aH, bH] of x(tau) = a0/2 + sum a_j cos + b_j sin
  double first_harmonic() const;  // hypot(a1, b1)
};

// `samples`: x at tau_i = 2 pi i / N, i = 0..N-1, N >= 2H + 1. The extremes are the extreme
// samples refined by a parabola through their neighbours (the sampling bias drops from
// O(1/N^2) to O(1/N^3) on a smooth peak).
PeriodSummary summarise_period(const Eigen::VectorXd& samples, int harmonics);

}  // namespace hbtrack
