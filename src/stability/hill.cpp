#include "hbtrack/stability/hill.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
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
  // Keep the 2n of smallest |Im l|, skipping copies l + i k w (k != 0) of one already kept: at a
  // period doubling the exponents sit on the strip edge, where s + i w/2 and s - i w/2 are the
  // same family, and keeping both would lose the other exponent crossing there.
  FloquetResult r;
  r.method = "hill";
  r.exponents.resize(2 * n);
  int kept = 0;
  const double tolerance = 1e-4 * omega;
  for (size_t i = 0; i < order.size() && kept < 2 * n; ++i) {
    const std::complex<double> l = all(order[i]);
    bool copy = false;
    for (int j = 0; j < kept && !copy; ++j) {
      const std::complex<double> d = l - r.exponents(j);
      const double shift = std::round(d.imag() / omega);
      copy = shift != 0.0 && std::abs(d.real()) <= tolerance && std::abs(d.imag() - shift * omega) <= tolerance;
    }
    if (!copy) r.exponents(kept++) = l;
  }
  r.exponents.conservativeResize(kept);
  finish_floquet(r, omega, 1e-9 * omega);
  return r;
}

}  // namespace hbtrack
