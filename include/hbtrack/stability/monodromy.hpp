#pragma once
// Floquet multipliers from the monodromy matrix: the variational equation
//   M y'' + (C + df/dv(t)) y' + (K + df/dx(t)) y = 0
// of the full model, linearised along the periodic solution and integrated over one period
// (classical RK4 with `steps` steps, the linearisation evaluated exactly at each stage time).
// An independent check of Hill's method; it ignores Lanczos filtering, which only exists in
// the frequency domain.
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/stability/floquet.hpp"

namespace hbtrack {

FloquetResult monodromy_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int steps);

}  // namespace hbtrack
