#include "hbtrack/hbm/fourier_basis.hpp"

#include <cmath>
#include <numbers>
#include <numeric>
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

std::vector<int> up_to(int harmonics) {
  if (harmonics < 0) throw std::invalid_argument("harmonics must be >= 0, got " + std::to_string(harmonics));
  std::vector<int> all(static_cast<size_t>(harmonics + 1));
  std::iota(all.begin(), all.end(), 0);
  return all;
}
}  // namespace

FourierBasis::FourierBasis(int harmonics, int samples) : FourierBasis(up_to(harmonics), samples) {}

FourierBasis::FourierBasis(std::vector<int> harmonic_numbers, int samples)
    : harmonics_(0), samples_(samples), numbers_(std::move(harmonic_numbers)) {
  if (numbers_.empty()) throw std::invalid_argument("harmonics: the list is empty");
  for (size_t i = 0; i < numbers_.size(); ++i) {
    if (numbers_[i] < 0) throw std::invalid_argument("harmonics must be >= 0, got " + std::to_string(numbers_[i]));
    if (i > 0 && numbers_[i] <= numbers_[i - 1]) throw std::invalid_argument("harmonics: the list must be sorted and unique");
  }
  harmonics_ = numbers_.back();
  if (samples < 2 * harmonics_ + 1)
    throw std::invalid_argument("samples must be >= 2*harmonics+1 = " + std::to_string(2 * harmonics_ + 1) + ", got " +
                                std::to_string(samples));
  build();
}

void FourierBasis::build() {
  for (int k : numbers_) {
    if (k == 0) {
      harmonic_of_.push_back(0);
      dense_index_.push_back(0);
    } else {
      harmonic_of_.insert(harmonic_of_.end(), {k, k});
      dense_index_.insert(dense_index_.end(), {2 * k - 1, 2 * k});
    }
  }
  const int nc = coefficients();
  synthesis_.resize(samples_, nc);
  derivative_synthesis_.resize(samples_, nc);
  analysis_.resize(nc, samples_);
  for (int i = 0; i < samples_; ++i) {
    const double tau = 2.0 * std::numbers::pi * i / samples_;
    for (int c = 0; c < nc; ++c) {
      const int k = harmonic_of(c);
      if (k == 0) {
        synthesis_(i, c) = 0.5;
        derivative_synthesis_(i, c) = 0.0;
        analysis_(c, i) = 2.0 / samples_;
      } else if (is_sine(c)) {
        synthesis_(i, c) = std::sin(k * tau);
        derivative_synthesis_(i, c) = k * std::cos(k * tau);
        analysis_(c, i) = 2.0 / samples_ * std::sin(k * tau);
      } else {
        synthesis_(i, c) = std::cos(k * tau);
        derivative_synthesis_(i, c) = -k * std::sin(k * tau);
        analysis_(c, i) = 2.0 / samples_ * std::cos(k * tau);
      }
    }
  }
  product_analysis_ = projection(2 * harmonics_, samples_);
}

int FourierBasis::cosine_index(int k) const {
  for (int c = 0; c < coefficients(); ++c)
    if (harmonic_of(c) == k && !is_sine(c)) return c;
  return -1;
}

Eigen::VectorXd FourierBasis::to_dense(const Eigen::VectorXd& coeffs, int dofs) const {
  if (coeffs.size() != static_cast<Eigen::Index>(dofs) * coefficients())
    throw std::invalid_argument("FourierBasis::to_dense: expected dofs * coefficients entries");
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs) * (2 * harmonics_ + 1));
  for (int c = 0; c < coefficients(); ++c) out.segment(dense_index(c) * dofs, dofs) = coeffs.segment(c * dofs, dofs);
  return out;
}

Eigen::VectorXd FourierBasis::from_dense(const Eigen::VectorXd& dense, int dofs) const {
  if (dense.size() != static_cast<Eigen::Index>(dofs) * (2 * harmonics_ + 1))
    throw std::invalid_argument("FourierBasis::from_dense: expected dofs * (2H+1) entries");
  Eigen::VectorXd out(static_cast<Eigen::Index>(dofs) * coefficients());
  for (int c = 0; c < coefficients(); ++c) out.segment(c * dofs, dofs) = dense.segment(dense_index(c) * dofs, dofs);
  return out;
}

void FourierBasis::product_matrix(const double* g, Eigen::Ref<Eigen::MatrixXd> out) const {
  // A(m), B(m): cosine and sine coefficients of g, with A(-m) = A(m), B(-m) = -B(m).
  auto A = [g](int m) {
    m = m < 0 ? -m : m;
    return m == 0 ? g[0] : g[2 * m - 1];
  };
  auto B = [g](int m) {
    if (m == 0) return 0.0;
    return m > 0 ? g[2 * m] : -g[-2 * m];
  };
  const int nc = coefficients();
  for (int col = 0; col < nc; ++col) {
    const int c = harmonic_of(col);
    const bool col_sine = is_sine(col);
    for (int row = 0; row < nc; ++row) {
      const int r = harmonic_of(row);
      const bool row_sine = is_sine(row);
      double v;
      if (r == 0 && c == 0) {
        v = 0.5 * A(0);
      } else if (r == 0) {
        v = col_sine ? B(c) : A(c);
      } else if (c == 0) {
        v = 0.5 * (row_sine ? B(r) : A(r));
      } else if (!row_sine && !col_sine) {
        v = 0.5 * (A(r - c) + A(r + c));  // cos r . cos c
      } else if (!row_sine) {
        v = 0.5 * (B(c + r) + B(c - r));  // cos r . sin c
      } else if (!col_sine) {
        v = 0.5 * (B(r + c) + B(r - c));  // sin r . cos c
      } else {
        v = 0.5 * (A(r - c) - A(r + c));  // sin r . sin c
      }
      out(row, col) = v;
    }
  }
}

void FourierBasis::right_multiply_derivative(Eigen::Ref<Eigen::MatrixXd> m) const {
  // nabla_j = j [[0, 1], [-1, 0]]: column a_j <- -j * column b_j, column b_j <- j * column a_j.
  for (int c = 0; c < coefficients(); ++c) {
    const int j = harmonic_of(c);
    if (j == 0) {
      m.col(c).setZero();
    } else if (!is_sine(c)) {
      Eigen::VectorXd a = m.col(c);
      m.col(c) = -j * m.col(c + 1);
      m.col(c + 1) = j * a;
    }
  }
}

void FourierBasis::derivative(const Eigen::VectorXd& coeffs, int dofs, Eigen::VectorXd& out) const {
  out.setZero(coeffs.size());
  for (int c = 0; c < coefficients(); ++c) {
    const int j = harmonic_of(c);
    if (j == 0 || is_sine(c)) continue;
    // x = a cos + b sin  ->  x' = j b cos - j a sin
    out.segment(c * dofs, dofs) = j * coeffs.segment((c + 1) * dofs, dofs);
    out.segment((c + 1) * dofs, dofs) = -j * coeffs.segment(c * dofs, dofs);
  }
}

}  // namespace hbtrack
