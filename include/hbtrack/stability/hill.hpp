#pragma once
// Hill's method: Floquet exponents from the quadratic eigenproblem of the harmonic balance
// linearisation on the full (uncondensed) system, (l^2 D2 + l D1 + J) p = 0 (method notes 5),
// keeping the 2n eigenvalues of smallest |Im l| (the sorting of Colaitis & Batailly, JSV 2022).
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/stability/floquet.hpp"

namespace hbtrack {

FloquetResult hill_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega);

}  // namespace hbtrack
