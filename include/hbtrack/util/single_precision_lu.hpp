#pragma once
// LU factors of a double matrix rounded to single precision, for an approximate Newton matrix:
// the continuation's corrector takes chord steps on them, each residual evaluated in double, so
// the factors' rounding (relative error about cond(A) * 6e-8 in a step) slows the contraction
// without changing the point converged to. sgetrf runs about 1.7x faster than dgetrf on the
// 568-unknown matrices of rotor 67 (bench/bench_single_precision_lu.cpp). OpenBLAS's sgetrf/sgetrs
// when the build found it, Eigen's PartialPivLU<MatrixXf> otherwise.
#include <Eigen/Dense>
#include <vector>

namespace hbtrack {

class SinglePrecisionLU {
 public:
  void compute(const Eigen::MatrixXd& a);  // a square; its factors replace the previous ones
  Eigen::Index size() const { return factors_.rows(); }
  // b <- A^-1 b, the solve in single precision: false (b unchanged) when it is not finite
  // (a zero or overflowing pivot), so that the caller factors in double instead.
  bool solve_in_place(Eigen::VectorXd& b) const;

 private:
  Eigen::MatrixXf factors_;
  std::vector<int> pivots_;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation_;
  mutable Eigen::VectorXf work_;
};

}  // namespace hbtrack
