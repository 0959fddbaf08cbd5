#pragma once
// The bordering machinery shared by the real fold systems and the complex Hill-pencil system:
// approximate null vectors by inverse iteration, and the bordered matrix [[A, b], [c^H, 0]].
#include <Eigen/Dense>
#include <stdexcept>

namespace hbtrack {

// `solve(y)` and `solve_adjoint(y)` apply A^-1 and A^-H (factors of A kept by the caller). A
// start with every component present; inverse iteration converges by the ratio of the two
// smallest singular values per step, and near a singular point the smallest is near zero.
template <class Vector, class Solve, class SolveAdjoint>
void inverse_iteration_null_vectors(Eigen::Index size, const Solve& solve, const SolveAdjoint& solve_adjoint, Vector& right, Vector& left) {
  right = Eigen::VectorXd::LinSpaced(size, 1.0, 2.0).normalized().cast<typename Vector::Scalar>();
  left = right;
  for (int it = 0; it < 4; ++it) {
    right = Vector(solve(right)).normalized();
    left = Vector(solve_adjoint(left)).normalized();
  }
  if (!right.allFinite() || !left.allFinite()) throw std::runtime_error("the Jacobian at the start has no usable null vector");
}

// out = [[a, b], [c^H, 0]] (c^T for real c), resized; a kept workspace.
template <class Matrix, class Vector>
void fill_bordered_matrix(const Matrix& a, const Vector& b, const Vector& c, Matrix& out) {
  const Eigen::Index n = a.rows();
  out.resize(n + 1, n + 1);
  out.topLeftCorner(n, n) = a;
  out.topRightCorner(n, 1) = b;
  out.bottomLeftCorner(1, n) = c.adjoint();
  out(n, n) = 0.0;
}

}  // namespace hbtrack
