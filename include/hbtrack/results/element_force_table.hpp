#pragma once
// element_forces.csv (frc --element-forces, docs/outputs.md): per branch point, the force of every
// nonlinear element on each of its dofs, as harmonics and extremes over the period.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack {

// omega, then per element i (elements[i] of the case) and per dof DOF of it:
// elementI_DOF_h0 (the mean), _cK, _sK per harmonic balanced, _max, _min over the AFT's N samples.
std::vector<std::string> element_force_header(const HarmonicBalance& hbm);
std::vector<double> element_force_row(HarmonicBalance& hbm, double omega, const Eigen::VectorXd& x);

}  // namespace hbtrack
