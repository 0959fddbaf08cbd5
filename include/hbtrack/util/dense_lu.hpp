#pragma once
// LU factorization with partial pivoting of a dense square matrix, P A = L U, and solves with
// its factors: the continuation's linear algebra (Newton steps, tangents, fold borders).
// Backed by LAPACK's dgetrf/dgetrs from OpenBLAS when the build found it (HBTRACK_OPENBLAS;
// 2.5-4x faster than Eigen's blocked LU compiled without -march=native, README Performance),
// run on one thread; otherwise by Eigen's PartialPivLU. The storage is kept between
// factorizations of the same size, so a Newton loop that calls compute() allocates nothing.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace hbtrack {

class DenseLU {
 public:
  DenseLU() = default;
  explicit DenseLU(const Eigen::MatrixXd& a) { compute(a); }
  void compute(const Eigen::MatrixXd& a);  // a square; its factors replace the previous ones
  Eigen::Index size() const { return factors_.rows(); }

  void solve_in_place(Eigen::VectorXd& b) const;             // b <- A^-1 b
  void solve_transposed_in_place(Eigen::VectorXd& b) const;  // b <- A^-T b
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::VectorXd solve_transposed(const Eigen::VectorXd& b) const;

  // det A = determinant_sign() * exp(log_abs_determinant()); sign 0 for an exactly zero pivot.
  double log_abs_determinant() const;
  int determinant_sign() const;
  // "OpenBLAS (core name)" or "Eigen": what compute() runs, for benchmark reports.
  static std::string backend();

 private:
  Eigen::MatrixXd factors_;  // L below the diagonal (unit diagonal implied), U on and above
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation_;  // P
  std::vector<int> pivots_;                                                    // dgetrf's row swaps (1-based), kept to avoid an allocation
};

// Solves A x = e_last (the last unit vector: a bordered system's right-hand side) by iterative
// refinement from the factors of a nearby matrix A0: x <- x + A0^-1 (e - A x), which converges
// when ||A0^-1 (A - A0)|| < 1. Stops at a backward error of a few hundred ulps (1e-13 ||A||
// ||x||), what a fresh LU attains, within `max_steps`; false when it does not get there.
// `residual` is a workspace.
bool refine_last_unit_solution(const DenseLU& nearby, const Eigen::MatrixXd& a, Eigen::VectorXd& x, Eigen::VectorXd& residual,
                               int max_steps = 8);

// ||M||_1 of an n x n operator known by its products, M v and M^T v (each in place), from a
// few of them (Hager's method with Higham's extra test vector, as LAPACK's condition
// estimates): a lower bound, in practice within a small factor of the true norm.
double estimate_norm1(Eigen::Index n, const std::function<void(Eigen::VectorXd&)>& apply,
                      const std::function<void(Eigen::VectorXd&)>& apply_transposed);

}  // namespace hbtrack
