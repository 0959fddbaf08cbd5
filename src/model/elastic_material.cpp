#include "hbtrack/model/elastic_material.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

void IsotropicMaterial::validate() const {
  if (!(youngs_modulus > 0) || !std::isfinite(youngs_modulus)) throw std::invalid_argument("material: Young's modulus must be > 0");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) throw std::invalid_argument("material: Poisson ratio must be in (-1, 0.5)");
  if (!(density > 0) || !std::isfinite(density)) throw std::invalid_argument("material: density must be > 0");
}

Eigen::Matrix<double, 6, 6> IsotropicMaterial::elasticity_matrix() const {
  const double e = youngs_modulus, nu = poisson_ratio;
  const double lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double shear = e / (2.0 * (1.0 + nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lambda);
  d.topLeftCorner<3, 3>().diagonal().array() += 2.0 * shear;
  d.bottomRightCorner<3, 3>().diagonal().setConstant(shear);
  return d;
}

}  // namespace hbtrack
