// The elements' own forces at a solution, for the results (element_forces.csv): the samples the
// AFT computes, kept per element instead of summed onto the retained dofs.
#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack {

std::vector<Eigen::MatrixXd> HarmonicBalance::element_force_samples(const Eigen::VectorXd& x, double omega) {
  const Eigen::VectorXd r_linear = residual_elements_ ? linear_residual(x, omega) : Eigen::VectorXd();
  sample(x, omega);
  std::vector<Eigen::MatrixXd> forces;
  for (size_t e = 0; e < elements_.size(); ++e) {
    evaluate_element(e, omega, r_linear, false);
    forces.push_back(slots_[e].response.force);
  }
  return forces;
}

}  // namespace hbtrack
