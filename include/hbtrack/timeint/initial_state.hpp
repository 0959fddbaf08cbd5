#pragma once
// Initial states for time integration: rest, or a point of a periodic (harmonic balance)
// solution, so that a simulation can start on an HBM orbit and show whether it stays there.
#include <Eigen/Dense>

#include "hbtrack/timeint/time_integrator.hpp"

namespace hbtrack {

// x = 0, v = 0 at `time`.
MotionState rest_state(int dofs, double time = 0);

// The state at time t of the periodic motion x(tau) = a0/2 + sum_j a_j cos(j tau) + b_j sin(j tau),
// tau = omega t: x(t) and x'(t) = omega dx/dtau. `full` holds dofs (2H+1) coefficients,
// harmonic-major [a0, a1, b1, ..., aH, bH] per block of `dofs` (HarmonicBalance::expand).
MotionState state_from_harmonics(const Eigen::VectorXd& full, int dofs, int harmonics, double omega, double time = 0);

// N equally spaced samples (N x dofs) of one period of that motion, from t = 0: what the
// history elements' periodic steady state is computed from (EquationOfMotion::periodic_history).
Eigen::MatrixXd period_samples(const Eigen::VectorXd& full, int dofs, int harmonics, int samples);

}  // namespace hbtrack
