#pragma once
// Floquet multipliers by shooting: the periodic orbit of the full equation of motion nearest a
// harmonic balance solution, converged by Newton on z(T) - z(0) = 0 (z = [x; x']) with the
// monodromy matrix as its Jacobian, and the multipliers of that orbit's monodromy matrix.
//
// Unlike monodromy_floquet, which linearises along the truncated Fourier series, this sees the
// orbit the equation of motion really has: on a law that is not smooth the HBM orbit's ripple
// near a contact shifts the instants where the tangent stiffness jumps, enough to turn a
// multiplier near -1 the wrong side of the circle (NLvib's two-dof contact example at H = 21).
// `steps` steps per period (RK4 for the state, fourth-order Magnus for its variational equation),
// each cut where the state crosses a switching surface of a C0 law.
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/stability/floquet.hpp"

namespace hbtrack {

struct ShootingOutcome {
  bool converged = false;
  int newton_iterations = 0;
  double periodicity_error = 0;  // ||z(T) - z(0)||_inf / ||z(0)||_inf at the last iterate
  Eigen::VectorXd state;         // z(0) = [x; x'] of the converged orbit
};

// Throws std::invalid_argument for a history-dependent element (a pointwise law is needed).
// When shooting does not converge, the result holds the multipliers of the last iterate and
// `outcome.converged` is false.
FloquetResult shooting_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int steps, ShootingOutcome* outcome = nullptr);

}  // namespace hbtrack
