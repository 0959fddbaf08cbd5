#include "hbtrack/timeint/initial_state.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

MotionState rest_state(int dofs, double time) {
  return {time, Eigen::VectorXd::Zero(dofs), Eigen::VectorXd::Zero(dofs)};
}

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

}  // namespace hbtrack
