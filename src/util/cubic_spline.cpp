#include "hbtrack/util/cubic_spline.hpp"

#include <algorithm>
#include <stdexcept>

namespace hbtrack {

NaturalCubicSpline::NaturalCubicSpline(const Eigen::VectorXd& knots, const Eigen::MatrixXd& values)
    : knots_(knots), values_(values), second_derivatives_(Eigen::MatrixXd::Zero(values.rows(), values.cols())) {
  const Eigen::Index n = knots.size();
  if (n < 2) throw std::invalid_argument("cubic spline: needs at least 2 knots");
  if (values.rows() != n) throw std::invalid_argument("cubic spline: one row of values per knot");
  for (Eigen::Index i = 1; i < n; ++i)
    if (!(knots(i) > knots(i - 1))) throw std::invalid_argument("cubic spline: knots must increase strictly");
  if (n == 2) return;  // a straight line
  // Tridiagonal system for the interior second derivatives (natural ends: zero), Thomas algorithm.
  const Eigen::Index m = n - 2;
  Eigen::VectorXd diagonal(m), upper(m);
  Eigen::MatrixXd rhs(m, values.cols());
  for (Eigen::Index i = 1; i <= m; ++i) {
    const double h0 = knots(i) - knots(i - 1), h1 = knots(i + 1) - knots(i);
    diagonal(i - 1) = 2.0 * (h0 + h1);
    upper(i - 1) = h1;
    rhs.row(i - 1) = 6.0 * ((values.row(i + 1) - values.row(i)) / h1 - (values.row(i) - values.row(i - 1)) / h0);
  }
  for (Eigen::Index i = 1; i < m; ++i) {
    const double lower = knots(i + 1) - knots(i);  // h of row i's sub-diagonal
    const double factor = lower / diagonal(i - 1);
    diagonal(i) -= factor * upper(i - 1);
    rhs.row(i) -= factor * rhs.row(i - 1);
  }
  for (Eigen::Index i = m - 1; i >= 0; --i) {
    Eigen::RowVectorXd row = rhs.row(i);
    if (i + 1 < m) row -= upper(i) * second_derivatives_.row(i + 2);
    second_derivatives_.row(i + 1) = row / diagonal(i);
  }
}

Eigen::RowVectorXd NaturalCubicSpline::operator()(double t) const {
  const Eigen::Index n = knots_.size();
  const auto upper = std::upper_bound(knots_.data() + 1, knots_.data() + n - 1, t);
  const Eigen::Index i = (upper - knots_.data()) - 1;  // interval [t_i, t_{i+1}]
  const double h = knots_(i + 1) - knots_(i);
  const double a = (knots_(i + 1) - t) / h, b = (t - knots_(i)) / h;
  return a * values_.row(i) + b * values_.row(i + 1) +
         ((a * a * a - a) * second_derivatives_.row(i) + (b * b * b - b) * second_derivatives_.row(i + 1)) * (h * h / 6.0);
}

}  // namespace hbtrack
