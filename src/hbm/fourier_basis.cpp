#include "hbtrack/hbm/fourier_basis.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbtrack {

namespace {
// (2/N)[1; cos(j tau); sin(j tau)] rows up to order `order`.
Eigen::MatrixXd projection(int order, int samples) {
  Eigen::MatrixXd p(2 * order + 1, samples);
  for (int i = 0; i < samples; ++i) {
    const double tau = 2.0 * std::numbers::pi * i / samples;
    p(0, i) = 2.0 / samples;
    for (int j = 1; j <= order; ++j) {
      p(2 * j - 1, i) = 2.0 / samples * std::cos(j * tau);
      p(2 * j, i) = 2.0 / samples * std::sin(j * tau);
    }
  }
  return p;
}
}  // namespace

FourierBasis::FourierBasis(int harmonics, int samples) : harmonics_(harmonics), samples_(samples) {
  if (harmonics < 0) throw std::invalid_argument("harmonics must be >= 0, got " + std::to_string(harmonics));
  if (samples < 2 * harmonics + 1)
    throw std::invalid_argument("samples must be >= 2*harmonics+1 = " + std::to_string(2 * harmonics + 1) +
                                ", got " + std::to_string(samples));
  const int nc = coefficients();
  synthesis_.resize(samples, nc);
  derivative_synthesis_.resize(samples, nc);
  for (int i = 0; i < samples; ++i) {
    const double tau = 2.0 * std::numbers::pi * i / samples;
    synthesis_(i, 0) = 0.5;
    derivative_synthesis_(i, 0) = 0.0;
    for (int j = 1; j <= harmonics; ++j) {
      const double c = std::cos(j * tau), s = std::sin(j * tau);
      synthesis_(i, 2 * j - 1) = c;
      synthesis_(i, 2 * j) = s;
      derivative_synthesis_(i, 2 * j - 1) = -j * s;
      derivative_synthesis_(i, 2 * j) = j * c;
    }
  }
  analysis_ = projection(harmonics, samples);
  product_analysis_ = projection(2 * harmonics, samples);
}

void FourierBasis::product_matrix(const double* g, Eigen::Ref<Eigen::MatrixXd> out) const {
  // A(m), B(m): cosine and sine coefficients of g, with A(-m) = A(m), B(-m) = -B(m).
  auto A = [g](int m) { m = m < 0 ? -m : m; return m == 0 ? g[0] : g[2 * m - 1]; };
  auto B = [g](int m) {
    if (m == 0) return 0.0;
    return m > 0 ? g[2 * m] : -g[-2 * m];
  };
  const int h = harmonics_;
  out(0, 0) = 0.5 * A(0);
  for (int l = 1; l <= h; ++l) {
    out(0, 2 * l - 1) = A(l);
    out(0, 2 * l) = B(l);
    out(2 * l - 1, 0) = 0.5 * A(l);
    out(2 * l, 0) = 0.5 * B(l);
  }
  for (int r = 1; r <= h; ++r) {
    for (int c = 1; c <= h; ++c) {
      out(2 * r - 1, 2 * c - 1) = 0.5 * (A(r - c) + A(r + c));  // cos r . cos c
      out(2 * r - 1, 2 * c) = 0.5 * (B(c + r) + B(c - r));      // cos r . sin c
      out(2 * r, 2 * c - 1) = 0.5 * (B(r + c) + B(r - c));      // sin r . cos c
      out(2 * r, 2 * c) = 0.5 * (A(r - c) - A(r + c));          // sin r . sin c
    }
  }
}

void FourierBasis::right_multiply_derivative(Eigen::Ref<Eigen::MatrixXd> m) const {
  // nabla_j = j [[0, 1], [-1, 0]]: column a_j <- -j * column b_j, column b_j <- j * column a_j.
  for (int j = 1; j <= harmonics_; ++j) {
    Eigen::VectorXd a = m.col(2 * j - 1);
    m.col(2 * j - 1) = -j * m.col(2 * j);
    m.col(2 * j) = j * a;
  }
  m.col(0).setZero();
}

void FourierBasis::derivative(const Eigen::VectorXd& coeffs, int dofs, Eigen::VectorXd& out) const {
  out.setZero(coeffs.size());
  for (int j = 1; j <= harmonics_; ++j) {
    // x = a cos + b sin  ->  x' = j b cos - j a sin
    out.segment((2 * j - 1) * dofs, dofs) = j * coeffs.segment(2 * j * dofs, dofs);
    out.segment(2 * j * dofs, dofs) = -j * coeffs.segment((2 * j - 1) * dofs, dofs);
  }
}

}  // namespace hbtrack
