#pragma once
// Isotropic linear elastic material of the solid finite elements (SI units in the blade model).
#include <Eigen/Dense>

namespace hbtrack {

struct IsotropicMaterial {
  double youngs_modulus = 0;  // E
  double poisson_ratio = 0;   // nu, in (-1, 0.5)
  double density = 0;         // rho

  // Throws std::invalid_argument naming the rule broken.
  void validate() const;
  // Stress from engineering strain, Voigt order [xx, yy, zz, yz, xz, xy].
  Eigen::Matrix<double, 6, 6> elasticity_matrix() const;
};

}  // namespace hbtrack
