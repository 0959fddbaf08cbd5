#pragma once
// Hill's method: Floquet exponents from the quadratic eigenproblem of the harmonic balance
// linearisation on the full (uncondensed) system, (l^2 D2 + l D1 + J) p = 0 (method notes 5),
// keeping the 2n eigenvalues of smallest |Im l| (the sorting of Colaitis & Batailly, JSV 2022).
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/stability/floquet.hpp"

namespace hbtrack {

// solver: dense (QR on the whole 2n(2H+1) spectrum), arnoldi (shift-invert Arnoldi for the
// min(2n, 24) eigenvalues nearest the imaginary axis, one LU of the n(2H+1) pencil per point) or automatic
// (dense up to a first-order size of 300).
FloquetResult hill_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, HillSolver solver = HillSolver::automatic);

}  // namespace hbtrack
