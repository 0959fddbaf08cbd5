#pragma once
// Ways a user states damping, turned into a damping matrix C.
#include <Eigen/Dense>

namespace hbtrack {

// C = alpha M + beta K.
Eigen::MatrixXd rayleigh_damping(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness, double alpha, double beta);

// C = M Phi diag(2 zeta_r w_r) Phi^T M with Phi the mass-normalised undamped modes sorted by
// frequency. `ratios` gives zeta per mode; modes beyond its length take its last value.
Eigen::MatrixXd modal_damping(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& ratios);

// Undamped modes: K phi = w^2 M phi, mass-normalised, sorted by increasing w.
struct NormalModes {
  Eigen::VectorXd frequencies;  // rad/s
  Eigen::MatrixXd shapes;       // n x n, columns mass-normalised
};
NormalModes normal_modes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness);

}  // namespace hbtrack
