#include "hbtrack/model/damping.hpp"

#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace hbtrack {

Eigen::MatrixXd rayleigh_damping(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness, double alpha, double beta) {
  return alpha * mass + beta * stiffness;
}

NormalModes normal_modes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
  if (solver.info() != Eigen::Success) throw std::runtime_error("normal modes: generalized eigenproblem failed");
  NormalModes modes;
  // Eigen returns eigenvalues in increasing order and M-normalised vectors.
  modes.frequencies = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  modes.shapes = solver.eigenvectors();
  return modes;
}

Eigen::MatrixXd modal_damping(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& ratios) {
  if (ratios.size() == 0) throw std::invalid_argument("damping.ratios: needs at least one value");
  const NormalModes modes = normal_modes(mass, stiffness);
  const Eigen::Index n = modes.frequencies.size();
  Eigen::VectorXd c(n);
  for (Eigen::Index r = 0; r < n; ++r) c(r) = 2.0 * ratios(std::min(r, ratios.size() - 1)) * modes.frequencies(r);
  const Eigen::MatrixXd m_phi = mass * modes.shapes;
  return m_phi * c.asDiagonal() * m_phi.transpose();
}

}  // namespace hbtrack
