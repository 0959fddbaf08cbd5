#pragma once
// Floquet multipliers from the monodromy matrix: the variational equation
//   M y'' + (C + df/dv(t)) y' + (K + df/dx(t)) y + df/dz(t) z = 0
// of the full model, linearised along the periodic solution and integrated over one period
// (classical RK4 with `steps` steps, the linearisation evaluated exactly at each stage time).
// History elements (friction sliders) add their internal variables z: frozen over a step, as in
// time integration, then moved by the linearised return mapping at its end (a stuck slider keeps
// its z and acts as its spring, a slipping one follows the displacement and transmits nothing).
// The multiplier of a slider that sticks over the whole period is 1 exactly (its position is
// neutral) and is left out; one that slips forgets its position (multiplier 0): the 2n
// multipliers of largest modulus are returned. Transitions between stick and slip fall on the
// step grid, so with history elements the multipliers converge as O(1/steps).
// An independent check of Hill's method; it ignores Lanczos filtering, which only exists in
// the frequency domain.
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/stability/floquet.hpp"

namespace hbtrack {

FloquetResult monodromy_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int steps);

}  // namespace hbtrack
