#include "hbtrack/model/sparse_modes.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace hbtrack {

namespace {

// y = (K - sigma M)^-1 x with a symmetric sparse LDL^T: half the memory and time of the SparseLU
// that Spectra's own SymShiftInvert uses for sparse matrices. At sigma = 0 a factor of K the
// caller already holds is used as it is (Craig-Bampton factors K_ii for its constraint modes:
// factoring it again was a quarter of a reduction's time).
class SparseShiftInvert {
 public:
  using Scalar = double;
  SparseShiftInvert(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                    const SparseLdlt* stiffness_factor)
      : stiffness_(stiffness), mass_(mass), stiffness_factor_(stiffness_factor) {}
  Eigen::Index rows() const { return stiffness_.rows(); }
  Eigen::Index cols() const { return stiffness_.cols(); }
  void set_shift(double sigma) {
    if (sigma == 0.0 && stiffness_factor_) {
      factor_in_use_ = stiffness_factor_;
      return;
    }
    own_factor_.compute(stiffness_ - sigma * mass_);
    if (own_factor_.info() != Eigen::Success || (own_factor_.vectorD().array() <= 0.0).any())
      throw std::runtime_error(
          "sparse modes: K - sigma M is not positive definite (rigid-body motion not constrained, or shift above the lowest mode)");
    factor_in_use_ = &own_factor_;
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y.noalias() = factor_in_use_->solve(x);
  }

 private:
  const Eigen::SparseMatrix<double>& stiffness_;
  const Eigen::SparseMatrix<double>& mass_;
  const SparseLdlt* stiffness_factor_;
  SparseLdlt own_factor_;
  const SparseLdlt* factor_in_use_ = nullptr;
};

// Eigenvectors come with an arbitrary sign; fixing it (largest entry positive) makes reduced
// models reproducible from one run, solver or machine to the next.
void fix_signs(Eigen::MatrixXd& shapes) {
  for (Eigen::Index c = 0; c < shapes.cols(); ++c) {
    Eigen::Index largest = 0;
    shapes.col(c).cwiseAbs().maxCoeff(&largest);
    if (shapes(largest, c) < 0.0) shapes.col(c) *= -1.0;
  }
}

NormalModes dense_lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass, int count) {
  const NormalModes all = normal_modes(Eigen::MatrixXd(mass), Eigen::MatrixXd(stiffness));
  NormalModes lowest{all.frequencies.head(count), all.shapes.leftCols(count)};
  fix_signs(lowest.shapes);
  return lowest;
}

NormalModes lowest_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass, int count, double shift,
                         const SparseLdlt* stiffness_factor) {
  const Eigen::Index n = stiffness.rows();
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n)
    throw std::runtime_error("sparse modes: K and M must be square and of the same size");
  if (count < 1 || count > n)
    throw std::runtime_error("sparse modes: asked for " + std::to_string(count) + " modes of a " + std::to_string(n) + "-dof model");
  // Lanczos needs a subspace of more than `count` vectors; below a few hundred dofs dense is as fast.
  const Eigen::Index subspace = std::max<Eigen::Index>(2 * count + 1, 20);
  if (n <= 300 || subspace >= n) return dense_lowest_modes(stiffness, mass, count);

  SparseShiftInvert op(stiffness, mass, stiffness_factor);
  Spectra::SparseSymMatProd<double> mass_product(mass);
  Spectra::SymGEigsShiftSolver<SparseShiftInvert, Spectra::SparseSymMatProd<double>, Spectra::GEigsMode::ShiftInvert> solver(
      op, mass_product, count, subspace, shift);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
  if (solver.info() != Spectra::CompInfo::Successful) throw std::runtime_error("sparse modes: the Lanczos iteration did not converge");
  const Eigen::VectorXd eigenvalues = solver.eigenvalues();
  const Eigen::MatrixXd vectors = solver.eigenvectors();
  std::vector<Eigen::Index> order(static_cast<size_t>(eigenvalues.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return eigenvalues(a) < eigenvalues(b); });
  NormalModes modes;
  modes.frequencies.resize(count);
  modes.shapes.resize(n, count);
  for (int r = 0; r < count; ++r) {
    const Eigen::Index source = order[static_cast<size_t>(r)];
    modes.frequencies(r) = std::sqrt(std::max(eigenvalues(source), 0.0));
    modes.shapes.col(r) = vectors.col(source);  // Spectra returns M-normalised vectors
  }
  fix_signs(modes.shapes);
  return modes;
}

}  // namespace

NormalModes lowest_sparse_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass, int count,
                                double shift) {
  return lowest_modes(stiffness, mass, count, shift, nullptr);
}

NormalModes lowest_sparse_modes(const SparseLdlt& stiffness_factor, const Eigen::SparseMatrix<double>& stiffness,
                                const Eigen::SparseMatrix<double>& mass, int count) {
  return lowest_modes(stiffness, mass, count, 0.0, &stiffness_factor);
}

}  // namespace hbtrack
