#include "hill_system.hpp"

namespace hbtrack {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// The cosine coefficient of a harmonic comes first: a coefficient is a sine when the one before
// it belongs to the same harmonic (j > 0 only).
bool is_sine(const FourierBasis& basis, int b) { return b > 0 && basis.harmonic_of(b - 1) == basis.harmonic_of(b); }

MatrixXd rows_cols(const MatrixXd& a, const std::vector<int>& rows, const std::vector<int>& cols) {
  MatrixXd out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
  for (size_t c = 0; c < cols.size(); ++c)
    for (size_t r = 0; r < rows.size(); ++r) out(static_cast<Index>(r), static_cast<Index>(c)) = a(rows[r], cols[c]);
  return out;
}

}  // namespace

MatrixXd HillSystem::linear_block(int br, int bc, double shift, const std::vector<int>& rows, const std::vector<int>& cols) const {
  const Index nr = static_cast<Index>(rows.size()), nc = static_cast<Index>(cols.size());
  const int j = basis->harmonic_of(br);
  if (basis->harmonic_of(bc) != j) return MatrixXd::Zero(nr, nc);
  const double jw = j * fundamental;
  if (br == bc) {
    const MatrixXd k = rows_cols(*stiffness, rows, cols), m = rows_cols(*mass, rows, cols), c = rows_cols(*damping, rows, cols);
    return k + (shift * shift - jw * jw) * m + shift * c;
  }
  const MatrixXd m = rows_cols(*mass, rows, cols), c = rows_cols(*damping, rows, cols);
  const MatrixXd cos_sin = jw * c + (2.0 * shift * jw) * m;  // the (cosine row, sine column) block
  return is_sine(*basis, bc) ? cos_sin : MatrixXd(-cos_sin);
}

VectorXd HillSystem::mass_times(const VectorXd& x) const {
  const Index n = dofs();
  VectorXd y(x.size());
  for (int b = 0; b < blocks(); ++b) y.segment(b * n, n).noalias() = *mass * x.segment(b * n, n);
  return y;
}

void HillSystem::prepare_products() { element_damping_sparse = element_damping.sparseView(); }

VectorXd HillSystem::damping_times(const VectorXd& x) const {
  const Index n = dofs();
  VectorXd y(x.size());
  for (int b = 0; b < blocks(); ++b) {
    y.segment(b * n, n).noalias() = *damping * x.segment(b * n, n);
    const double two_jw = 2.0 * basis->harmonic_of(b) * fundamental;
    if (two_jw == 0.0) continue;
    // Cosine row: + 2 j w M x_sine; sine row: - 2 j w M x_cosine.
    if (is_sine(*basis, b))
      y.segment(b * n, n).noalias() -= two_jw * (*mass * x.segment((b - 1) * n, n));
    else
      y.segment(b * n, n).noalias() += two_jw * (*mass * x.segment((b + 1) * n, n));
  }
  const Index c = static_cast<Index>(coupled.size());
  if (c == 0 || element_damping_sparse.nonZeros() == 0) return y;
  VectorXd xc(c * blocks());
  for (int b = 0; b < blocks(); ++b)
    for (Index i = 0; i < c; ++i) xc(b * c + i) = x(b * n + coupled[static_cast<size_t>(i)]);
  const VectorXd yc = element_damping_sparse * xc;
  for (int b = 0; b < blocks(); ++b)
    for (Index i = 0; i < c; ++i) y(b * n + coupled[static_cast<size_t>(i)]) += yc(b * c + i);
  return y;
}

void HillSystem::dense(MatrixXd& jacobian, MatrixXd& velocity) const {
  const int n = dofs();
  std::vector<int> all(static_cast<size_t>(n));
  for (int d = 0; d < n; ++d) all[static_cast<size_t>(d)] = d;
  jacobian.setZero(size(), size());
  velocity.setZero(size(), size());
  for (int br = 0; br < blocks(); ++br)
    for (int bc = 0; bc < blocks(); ++bc) {
      if (basis->harmonic_of(br) != basis->harmonic_of(bc)) continue;
      // J = P(0); D1 = (P(1) - P(-1)) / 2, exact for a quadratic in s.
      jacobian.block(br * n, bc * n, n, n) = linear_block(br, bc, 0.0, all, all);
      velocity.block(br * n, bc * n, n, n) = 0.5 * (linear_block(br, bc, 1.0, all, all) - linear_block(br, bc, -1.0, all, all));
    }
  const Index c = static_cast<Index>(coupled.size());
  for (Index r = 0; r < c * blocks(); ++r)
    for (Index q = 0; q < c * blocks(); ++q) {
      const Index row = (r / c) * n + coupled[static_cast<size_t>(r % c)], col = (q / c) * n + coupled[static_cast<size_t>(q % c)];
      jacobian(row, col) += element_jacobian(r, q);
      velocity(row, col) += element_damping(r, q);
    }
}

}  // namespace hbtrack
