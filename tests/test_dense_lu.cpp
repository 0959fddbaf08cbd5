// DenseLU (OpenBLAS's dgetrf when built with it, Eigen's LU otherwise) against Eigen's
// PartialPivLU: solves, transposed solves, determinant; the estimate of ||A^-1||_1 from them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "hbtrack/util/dense_lu.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_dense_lu {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using hbtrack::DenseLU;
using hbtrack::estimate_norm1;

namespace {
// log |det A| and its sign from Eigen's factors (det itself overflows for n = 300).
std::pair<double, int> reference_log_det(const Eigen::PartialPivLU<MatrixXd>& lu) {
  double log_abs = 0;
  int sign = static_cast<int>(lu.permutationP().determinant());
  for (Eigen::Index i = 0; i < lu.matrixLU().rows(); ++i) {
    log_abs += std::log(std::abs(lu.matrixLU()(i, i)));
    if (lu.matrixLU()(i, i) < 0) sign = -sign;
  }
  return {log_abs, sign};
}
}  // namespace

TEST(DenseLU, AgreesWithEigenOnWellConditionedSystems) {
  std::srand(3);
  DenseLU lu;  // one object for every size: its storage follows the matrix
  for (int n : {300, 1, 7, 60}) {
    // Random entries pivot (no diagonal dominance); n/4 on the diagonal keeps the condition
    // number below ~1e2, so two backward-stable solves agree to ~1e-13: 1e-10 relative
    // leaves three orders of magnitude for the differing operation order.
    MatrixXd a = MatrixXd::Random(n, n) + 0.25 * n * MatrixXd::Identity(n, n);
    if (n > 1) a.row(0).swap(a.row(1));  // a negative determinant
    const VectorXd b = VectorXd::Random(n);
    lu.compute(a);
    const Eigen::PartialPivLU<MatrixXd> reference(a);
    const VectorXd x = reference.solve(b), xt = reference.transpose().solve(b);
    EXPECT_LE((lu.solve(b) - x).norm(), 1e-10 * x.norm()) << n;
    EXPECT_LE((lu.solve_transposed(b) - xt).norm(), 1e-10 * xt.norm()) << n;
    const auto [log_abs, sign] = reference_log_det(reference);
    EXPECT_NEAR(lu.log_abs_determinant(), log_abs, 1e-10 * std::max(1.0, std::abs(log_abs))) << n;
    EXPECT_EQ(lu.determinant_sign(), sign) << n;
  }
}

TEST(DenseLU, InverseNormEstimateIsALowerBoundWithinAFactorOfThree) {
  std::srand(5);
  for (int n : {5, 40, 150}) {
    // Graded columns make the inverse's 1-norm come from one column, which the ascent must find.
    MatrixXd a = MatrixXd::Random(n, n) + 0.25 * n * MatrixXd::Identity(n, n);
    for (int j = 0; j < n; ++j) a.col(j) *= std::pow(10.0, 3.0 * j / n);
    const double exact = a.inverse().cwiseAbs().colwise().sum().maxCoeff();
    const DenseLU lu(a);
    const double estimate = estimate_norm1(
        n, [&](VectorXd& v) { lu.solve_in_place(v); }, [&](VectorXd& v) { lu.solve_transposed_in_place(v); });
    EXPECT_LE(estimate, exact * (1 + 1e-10)) << n;  // the norm of A^-1 x for some unit x
    EXPECT_GE(estimate, exact / 3) << n;            // Hager's estimate is rarely worse (Higham 1988)
  }
}

}  // namespace hbtrack_tests::file_dense_lu
