#pragma once
// Hill's matrices in structured form, as the shift-invert solver needs them: the model's linear
// part couples dofs only within one harmonic (the cosine and sine of harmonic j), so it is read
// from K, M and C when needed; the nonlinear elements couple every harmonic, but only on the dofs
// they touch, so their blocks are kept dense in that smaller layout. On the blade (27 of 39 dofs
// coupled, H = 10) this replaces two dense 819 x 819 matrices, formed at every point, by two of
// 567; on a 128-mass chain with one contact dof, two of 2688 by two of 21.
//
// The quadratic pencil is P(s) = J + s D1 + s^2 D2 with D2 = I x M and, per harmonic j (w the
// fundamental), on its cosine block a and sine block b:
//   J[a,a] = J[b,b] = K - (j w)^2 M,  J[a,b] = -J[b,a] = j w C;
//   D1[a,a] = D1[b,b] = C,            D1[a,b] = -D1[b,a] = 2 j w M;
// plus the elements' blocks on the coupled dofs (HarmonicBalance::hill_matrices, the dense form).
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "hbtrack/hbm/fourier_basis.hpp"

namespace hbtrack {

struct HillSystem {
  const Eigen::MatrixXd* stiffness = nullptr;  // K, M, C: n x n, the model's
  const Eigen::MatrixXd* mass = nullptr;
  const Eigen::MatrixXd* damping = nullptr;
  const FourierBasis* basis = nullptr;  // its coefficients are the blocks, harmonic_of() their harmonic
  double fundamental = 0;               // w: basis harmonic j is at j w
  std::vector<int> coupled;             // model dofs the elements touch, ascending
  // The elements' parts of J and D1 on the coupled dofs: (c nc) square, harmonic-major over
  // `coupled` (row b c + i: coefficient b of coupled dof i).
  Eigen::MatrixXd element_jacobian, element_damping;
  Eigen::SparseMatrix<double> element_damping_sparse;

  int dofs() const { return static_cast<int>(mass->rows()); }
  int blocks() const { return basis->coefficients(); }
  Eigen::Index size() const { return static_cast<Eigen::Index>(dofs()) * blocks(); }
  // The linear part of P(s) between coefficient blocks br and bc (n x n; zero unless both are of
  // one harmonic), restricted to the model dofs `rows` x `cols`.
  Eigen::MatrixXd linear_block(int br, int bc, double shift, const std::vector<int>& rows, const std::vector<int>& cols) const;
  // y = D1 x (size n nc), without forming D1; the elements' part through a sparse copy of
  // element_damping (a few percent of it is nonzero: only dofs of one element couple), made by
  // prepare_products() after element_damping changes.
  void prepare_products();
  Eigen::VectorXd damping_times(const Eigen::VectorXd& x) const;
  // y = D2 x = (I x M) x.
  Eigen::VectorXd mass_times(const Eigen::VectorXd& x) const;
  // The dense J and D1 (for checks and small systems).
  void dense(Eigen::MatrixXd& jacobian, Eigen::MatrixXd& velocity) const;
};

}  // namespace hbtrack
