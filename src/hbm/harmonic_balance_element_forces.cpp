// The elements' own forces at a solution, for the results (element_forces.csv): the samples the
// AFT computes, kept per element instead of summed onto the retained dofs.
#include "hbtrack/hbm/harmonic_balance_system.hpp"

namespace hbtrack {

std::vector<Eigen::MatrixXd> HarmonicBalanceSystem::element_force_samples(const ParameterValues& p, HarmonicBalanceWorkspace& ws,
                                                                          const Eigen::VectorXd& x, double omega) const {
  check(p, ws);
  const Eigen::VectorXd r_linear = residual_elements_ ? linear_residual(p, ws, x, omega) : Eigen::VectorXd();
  sample(ws, x, omega);
  std::vector<Eigen::MatrixXd> forces;
  for (size_t e = 0; e < elements_.size(); ++e) {
    evaluate_element(p, ws, e, omega, r_linear, false);
    forces.push_back(ws.elements_[e].response.force);
  }
  return forces;
}

}  // namespace hbtrack
