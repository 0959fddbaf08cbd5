#include "hbtrack/timeint/initial_state.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hbtrack {

MotionState rest_state(int dofs, double time) { return {time, Eigen::VectorXd::Zero(dofs), Eigen::VectorXd::Zero(dofs)}; }

MotionState state_from_harmonics(const Eigen::VectorXd& full, int dofs, int harmonics, double omega, double time) {
  if (full.size() != static_cast<Eigen::Index>(dofs) * (2 * harmonics + 1))
    throw std::invalid_argument("state_from_harmonics: expected dofs * (2H+1) coefficients");
  const double tau = omega * time;
  MotionState s{time, 0.5 * full.head(dofs), Eigen::VectorXd::Zero(dofs)};
  for (int j = 1; j <= harmonics; ++j) {
    const auto a = full.segment((2 * j - 1) * dofs, dofs);
    const auto b = full.segment(2 * j * dofs, dofs);
    const double c = std::cos(j * tau), sn = std::sin(j * tau);
    s.x += c * a + sn * b;
    s.v += (omega * j) * (-sn * a + c * b);
  }
  return s;
}

Eigen::MatrixXd period_samples(const Eigen::VectorXd& full, int dofs, int harmonics, int samples) {
  if (full.size() != static_cast<Eigen::Index>(dofs) * (2 * harmonics + 1))
    throw std::invalid_argument("period_samples: expected dofs * (2H+1) coefficients");
  const Eigen::Map<const Eigen::MatrixXd> coefficients(full.data(), dofs, 2 * harmonics + 1);
  Eigen::MatrixXd basis(samples, 2 * harmonics + 1);
  for (int t = 0; t < samples; ++t) {
    const double tau = 2.0 * std::numbers::pi * t / samples;
    basis(t, 0) = 0.5;
    for (int j = 1; j <= harmonics; ++j) basis(t, 2 * j - 1) = std::cos(j * tau), basis(t, 2 * j) = std::sin(j * tau);
  }
  return basis * coefficients.transpose();
}

}  // namespace hbtrack
