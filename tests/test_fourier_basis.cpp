// The real Fourier basis and the Toeplitz-plus-Hankel product matrices of the AFT Jacobian.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/hbm/fourier_basis.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_fourier_basis {

using hbtrack::FourierBasis;

TEST(FourierBasis, AnalysisInvertsSynthesisUpToH) {
  for (int h : {1, 3, 10}) {
    const FourierBasis b(h, 4 * h + 3);
    const Eigen::MatrixXd identity = b.analysis() * b.synthesis();
    EXPECT_LT((identity - Eigen::MatrixXd::Identity(2 * h + 1, 2 * h + 1)).cwiseAbs().maxCoeff(), 1e-12) << "H=" << h;
  }
}

TEST(FourierBasis, DerivativeSynthesisDifferentiatesSignals) {
  const FourierBasis b(4, 64);
  Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(9, -1.0, 1.0);
  Eigen::VectorXd dc;
  b.derivative(c, 1, dc);
  const Eigen::VectorXd v1 = b.derivative_synthesis() * c;
  const Eigen::VectorXd v2 = b.synthesis() * dc;
  EXPECT_LT((v1 - v2).cwiseAbs().maxCoeff(), 1e-12);
  // Against the analytic derivative of the series.
  for (int i = 0; i < 64; ++i) {
    const double tau = 2.0 * std::numbers::pi * i / 64;
    double expected = 0;
    for (int j = 1; j <= 4; ++j) expected += -j * c(2 * j - 1) * std::sin(j * tau) + j * c(2 * j) * std::cos(j * tau);
    EXPECT_NEAR(v1(i), expected, 1e-12);
  }
}

TEST(FourierBasis, ProductMatrixEqualsDenseAftProduct) {
  // Gamma^-1 diag(g) Gamma from the 4H+1 coefficients of g must equal the dense product for any
  // sampled g, including one with content above 2H (aliasing is handled identically).
  for (int n : {16, 33, 128}) {
    const int h = 5;
    const FourierBasis b(h, n);
    Eigen::VectorXd g(n);
    for (int i = 0; i < n; ++i) {
      const double tau = 2.0 * std::numbers::pi * i / n;
      g(i) = std::exp(std::sin(tau)) + 0.3 * std::cos(7 * tau) + std::abs(std::cos(tau));
    }
    const Eigen::MatrixXd dense = b.analysis() * g.asDiagonal() * b.synthesis();
    const Eigen::VectorXd coeffs = b.product_analysis() * g;
    Eigen::MatrixXd fast(2 * h + 1, 2 * h + 1);
    b.product_matrix(coeffs.data(), fast);
    EXPECT_LT((fast - dense).cwiseAbs().maxCoeff(), 1e-12) << "N=" << n;
  }
}

TEST(FourierBasis, RightMultiplyDerivativeMatchesOperator) {
  const FourierBasis b(3, 32);
  Eigen::MatrixXd m = Eigen::MatrixXd::Random(7, 7);
  Eigen::MatrixXd nabla = Eigen::MatrixXd::Zero(7, 7);
  for (int j = 1; j <= 3; ++j) {
    nabla(2 * j - 1, 2 * j) = j;
    nabla(2 * j, 2 * j - 1) = -j;
  }
  const Eigen::MatrixXd expected = m * nabla;
  b.right_multiply_derivative(m);
  EXPECT_LT((m - expected).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(FourierBasis, RejectsTooFewSamples) {
  EXPECT_THROW(FourierBasis(5, 10), std::invalid_argument);
  EXPECT_NO_THROW(FourierBasis(5, 11));
}

}  // namespace hbtrack_tests::file_fourier_basis
