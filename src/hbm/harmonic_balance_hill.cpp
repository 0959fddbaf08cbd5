// Hill's matrices of the harmonic balance linearisation (stability/hill.cpp): dense on the full
// system, or the elements' blocks alone on the dofs they touch.
#include <algorithm>
#include <stdexcept>

#include "hbtrack/hbm/harmonic_balance_system.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

void HarmonicBalanceSystem::hill_matrices(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x, double omega,
                                          MatrixXd& jacobian, MatrixXd& damping) const {
  refuse_residual_elements("Hill's stability method");
  check(p, ws);
  const int n = model_.dofs();
  const int nc = basis_.coefficients();
  const int size = n * nc;
  jacobian.setZero(size, size);
  damping.setZero(size, size);
  // Linear part per harmonic: [[K - (jw)^2 M, jw C], [-jw C, K - (jw)^2 M]] in the full
  // Jacobian; 2w (nabla x M) + I x C in the velocity matrix.
  const double w = fundamental(omega);
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const MatrixXd kd = model_.stiffness - (j * w) * (j * w) * model_.mass;
    const int a = slot_offset(slot) * n, b = a + n;
    if (j == 0) {
      jacobian.block(a, a, n, n) = kd;
      damping.block(a, a, n, n) = model_.damping;
      continue;
    }
    jacobian.block(a, a, n, n) = kd;
    jacobian.block(b, b, n, n) = kd;
    jacobian.block(a, b, n, n) = j * w * model_.damping;
    jacobian.block(b, a, n, n) = -j * w * model_.damping;
    damping.block(a, a, n, n) = model_.damping;
    damping.block(b, b, n, n) = model_.damping;
    damping.block(a, b, n, n) = 2.0 * w * j * model_.mass;
    damping.block(b, a, n, n) = -2.0 * w * j * model_.mass;
  }
  add_hill_element_blocks(
      p, ws, x, omega, n, [](int dof) { return dof; }, jacobian, damping);
}

void HarmonicBalanceSystem::hill_element_blocks(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x, double omega,
                                                const std::vector<int>& coupled, MatrixXd& jacobian, MatrixXd& damping) const {
  refuse_residual_elements("Hill's stability method");
  check(p, ws);
  const int c = static_cast<int>(coupled.size());
  const Eigen::Index size = static_cast<Eigen::Index>(c) * basis_.coefficients();
  jacobian.setZero(size, size);
  damping.setZero(size, size);
  const auto position = [&](int dof) {
    const auto at = std::lower_bound(coupled.begin(), coupled.end(), dof);
    if (at == coupled.end() || *at != dof) throw std::logic_error("hill_element_blocks: an element dof is not among the coupled dofs");
    return static_cast<int>(at - coupled.begin());
  };
  add_hill_element_blocks(p, ws, x, omega, c, position, jacobian, damping);
}

void HarmonicBalanceSystem::add_hill_element_blocks(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x, double omega,
                                                    int stride, const std::function<int(int)>& position, MatrixXd& jacobian,
                                                    MatrixXd& damping) const {
  sample(ws, x, omega);
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    ElementState& state = ws.elements_[e];
    element.evaluate(state.x, state.v, element_frequency(element, omega, options_.subharmonic), element.property_values(p), state.response,
                     false);
    std::vector<int> positions;
    for (int dof : element.dofs) positions.push_back(position(dof));
    // The velocity part enters the Jacobian as omega (F_v nabla) and D1 as F_v.
    add_element_blocks(ws, e, omega, stride, positions, &jacobian, nullptr);
    add_element_blocks(ws, e, omega, stride, positions, nullptr, &damping);
  }
}

}  // namespace hbtrack
