#pragma once
// A natural cubic spline through (t_i, y_i), t strictly increasing, several value columns at
// once: it passes through every knot exactly, which is what lets a meshed blade reproduce the
// published section points. Outside [t_0, t_n] it extends the end cubics.
#include <Eigen/Dense>

namespace hbtrack {

class NaturalCubicSpline {
 public:
  // `values` has one row per knot. Throws std::invalid_argument for fewer than 2 knots, knots
  // that do not increase strictly or a row count that differs from the knots'.
  NaturalCubicSpline(const Eigen::VectorXd& knots, const Eigen::MatrixXd& values);
  Eigen::RowVectorXd operator()(double t) const;
  double first_knot() const { return knots_(0); }
  double last_knot() const { return knots_(knots_.size() - 1); }

 private:
  Eigen::VectorXd knots_;
  Eigen::MatrixXd values_, second_derivatives_;
};

}  // namespace hbtrack
