#pragma once
// Floquet exponents and multipliers of a periodic solution of period T = 2 pi / omega: the 2n
// exponents l (n dofs) with multipliers mu = exp(l T). The solution is stable when every
// multiplier lies inside the unit circle (every exponent has a negative real part).
#include <Eigen/Dense>
#include <string>

namespace hbtrack {

struct FloquetResult {
  std::string method;          // "hill" or "monodromy"
  Eigen::VectorXcd exponents;  // 2n, sorted by increasing |Im l| (Hill) or from log(mu) / T
  Eigen::VectorXcd multipliers;
  double max_real = 0;         // largest real part of the exponents
  bool stable = true;
};

// Fills multipliers, max_real and stable from exponents. `tolerance` on max_real (in 1/s):
// a multiplier on the unit circle to round-off counts as stable.
void finish_floquet(FloquetResult& r, double omega, double tolerance);

// Test functions of the multipliers whose sign changes bracket bifurcations:
//   period doubling: prod (1 + mu_i)   (a real multiplier crosses -1)
//   Neimark-Sacker:  prod_{i<j} (mu_i mu_j - 1) over multipliers that are not real
//                    (a complex pair crosses the unit circle)
double period_doubling_test(const Eigen::VectorXcd& multipliers);
double neimark_sacker_test(const Eigen::VectorXcd& multipliers);

}  // namespace hbtrack
