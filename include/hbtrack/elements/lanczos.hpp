#pragma once
// Lanczos sigma factors: sigma_j = sinc(j / (H + 1))^p multiply the harmonic-j coefficients of
// a filtered force (a0 untouched), attenuating the Gibbs oscillations of contact forces.
#include <Eigen/Dense>

namespace hbtrack {

// One factor per real Fourier coefficient [a0, a1, b1, ..., aH, bH] (size 2H+1).
Eigen::VectorXd lanczos_factors(int harmonics, double exponent);

}  // namespace hbtrack
