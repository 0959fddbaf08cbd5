#include "hbtrack/stability/hill.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>

namespace hbtrack {

FloquetResult hill_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega) {
  const int n = hbm.model().dofs();
  Eigen::MatrixXd jacobian, damping;
  hbm.hill_matrices(x, omega, jacobian, damping);
  const Eigen::Index size = jacobian.rows();
  const int blocks = hbm.basis().coefficients();
  // First-order form [p; l p]: A = [[0, I], [-D2^-1 J, -D2^-1 D1]] with D2 = I x M.
  const Eigen::LLT<Eigen::MatrixXd> mass(hbm.model().mass);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * size, 2 * size);
  a.topRightCorner(size, size).setIdentity();
  for (int b = 0; b < blocks; ++b) {
    a.block(size + b * n, 0, n, size) = -mass.solve(jacobian.middleRows(b * n, n));
    a.block(size + b * n, size, n, size) = -mass.solve(damping.middleRows(b * n, n));
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, false);
  const Eigen::VectorXcd all = solver.eigenvalues();
  std::vector<Eigen::Index> order(static_cast<size_t>(all.size()));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index i, Eigen::Index j) { return std::abs(all(i).imag()) < std::abs(all(j).imag()); });
  FloquetResult r;
  r.method = "hill";
  r.exponents.resize(2 * n);
  for (int i = 0; i < 2 * n; ++i) r.exponents(i) = all(order[static_cast<size_t>(i)]);
  finish_floquet(r, omega, 1e-9 * omega);
  return r;
}

}  // namespace hbtrack
