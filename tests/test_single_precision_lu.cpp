// The chord corrector's single-precision factors (util/single_precision_lu.hpp): solves at
// single precision's accuracy, subnormals flushed without losing the solve, a matrix single
// precision cannot hold refused so that the corrector factors in double, and a continuation
// large enough to use them (m + 1 >= 128) locating its folds where double Newton does.
#include <gtest/gtest.h>

#include <cmath>

#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/util/single_precision_lu.hpp"

namespace hbtrack_tests::file_single_precision_lu {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

MatrixXd well_conditioned(int n) {
  MatrixXd a = MatrixXd::Random(n, n);
  a.diagonal().array() += n;  // diagonally dominant: condition number below 3
  return a;
}

// Relative backward error ||A x - b||_inf / (||A||_inf ||x||_inf).
double backward_error(const MatrixXd& a, const VectorXd& x, const VectorXd& b) {
  return (a * x - b).lpNorm<Eigen::Infinity>() / (a.cwiseAbs().rowwise().sum().maxCoeff() * x.lpNorm<Eigen::Infinity>());
}

// R_i = u_i^3 - 3 u_i + 0.05 (u_{i+1} - u_i) - lambda (cyclic): every component folds at
// u = +-1 (lambda = -+2) but for the weak coupling, the branch from lambda = -4 along the
// symmetric solution u_i = u. 151 unknowns: the chord corrector factors in single precision.
class CoupledFolds final : public hbtrack::ContinuationProblem {
 public:
  int size() const override { return kSize; }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jac, VectorXd* r_lambda) override {
    r.resize(kSize);
    for (int i = 0; i < kSize; ++i) r(i) = u(i) * u(i) * u(i) - 3 * u(i) + kCoupling * (u((i + 1) % kSize) - u(i)) - lambda;
    if (!jac) return;
    jac->setZero(kSize, kSize);
    for (int i = 0; i < kSize; ++i) {
      (*jac)(i, i) = 3 * u(i) * u(i) - 3 - kCoupling;
      (*jac)(i, (i + 1) % kSize) += kCoupling;
    }
    *r_lambda = VectorXd::Constant(kSize, -1.0);
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(kSize); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
  bool single_precision_chords() const override { return true; }
  static constexpr int kSize = 151;  // odd: the alternating mode (a real eigenvalue, a BP) does not exist
  static constexpr double kCoupling = 0.05;
};

}  // namespace

TEST(SinglePrecisionLU, SolvesToSinglePrecisionsAccuracy) {
  const MatrixXd a = well_conditioned(200);
  const VectorXd b = VectorXd::Random(200);
  hbtrack::SinglePrecisionLU lu;
  lu.compute(a);
  VectorXd x = b;
  ASSERT_TRUE(lu.solve_in_place(x));
  // A backward-stable solve in single precision: about sqrt(n) unit roundoffs (6e-8) in practice
  // (2.5e-7 here with OpenBLAS's kernels), n u = 1.2e-5 in the worst case.
  EXPECT_LT(backward_error(a, x, b), 1e-5);
  EXPECT_GT(backward_error(a, x, b), 1e-12);  // and not a double solve
}

TEST(SinglePrecisionLU, ColumnsSpanningSixtyDecadesStillSolve) {
  // A scaled Jacobian's columns: its elimination meets subnormal floats, which are flushed.
  MatrixXd a = well_conditioned(150);
  for (int j = 0; j < 150; ++j) a.col(j) *= std::pow(10.0, -30.0 + 60.0 * j / 149.0);
  const VectorXd column_scale = a.colwise().norm().transpose();
  const VectorXd x_true = VectorXd::Random(150).cwiseQuotient(column_scale);
  const VectorXd b = a * x_true;
  hbtrack::SinglePrecisionLU lu;
  lu.compute(a);
  VectorXd x = b;
  ASSERT_TRUE(lu.solve_in_place(x));
  // Partial pivoting is blind to column scaling: in the unknowns times their column's scale the
  // error is that of the unscaled, well-conditioned system (condition below 3), a few unit
  // roundoffs of single precision (6e-8) times the growth; 1e-5 leaves a factor 100 for that.
  const VectorXd error = (x - x_true).cwiseProduct(column_scale);
  EXPECT_LT(error.lpNorm<Eigen::Infinity>() / x_true.cwiseProduct(column_scale).lpNorm<Eigen::Infinity>(), 1e-5);
}

TEST(SinglePrecisionLU, RefusesAMatrixSinglePrecisionCannotHold) {
  const MatrixXd a = 1e-50 * well_conditioned(20);  // below the smallest float: zero in single
  hbtrack::SinglePrecisionLU lu;
  lu.compute(a);
  VectorXd x = VectorXd::Ones(20);
  EXPECT_FALSE(lu.solve_in_place(x));
  EXPECT_EQ(x, VectorXd::Ones(20));  // unchanged: the caller solves in double from b
}

TEST(SinglePrecisionLU, ChordCorrectorLocatesTheFoldsDoubleNewtonDoes) {
  CoupledFolds problem;
  const VectorXd u0 = VectorXd::Constant(CoupledFolds::kSize, -2.195823345445647);  // u^3 - 3u = -4
  hbtrack::ContinuationOptions chord;                                               // reuse_factorization: single-precision Newton matrices
  chord.step = 0.05;
  hbtrack::ContinuationOptions newton = chord;
  newton.reuse_factorization = false;  // a fresh double LU at every iteration
  const auto with_chords = hbtrack::continue_branch(problem, u0, -4.0, 4.0, chord);
  const auto with_newton = hbtrack::continue_branch(problem, u0, -4.0, 4.0, newton);
  ASSERT_EQ(with_chords.summary.stop_reason, hbtrack::StopReason::reached_end);
  ASSERT_EQ(with_chords.special_points.size(), 2u);
  ASSERT_EQ(with_newton.special_points.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    // The folds of u^3 - 3u = lambda at lambda = +-2 (the symmetric branch does not feel the
    // coupling), located to the corrector's tolerance either way.
    EXPECT_NEAR(with_chords.special_points[k].lambda, k == 0 ? 2.0 : -2.0, 1e-8);
    EXPECT_NEAR(with_chords.special_points[k].lambda, with_newton.special_points[k].lambda, 1e-9);
  }
}

}  // namespace hbtrack_tests::file_single_precision_lu
