#pragma once
// R(u, lambda) = u - lambda: a straight branch, so that nothing but a test's monitor sizes the
// continuation's steps (tests of the engine's monitor handling).
#include <Eigen/Dense>

#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack_tests {

class StraightBranch final : public hbtrack::ContinuationProblem {
 public:
  int size() const override { return 1; }
  void evaluate(const Eigen::VectorXd& u, double lambda, Eigen::VectorXd& r, Eigen::MatrixXd* jac, Eigen::VectorXd* r_lambda) override {
    r = Eigen::VectorXd::Constant(1, u(0) - lambda);
    if (jac) {
      *jac = Eigen::MatrixXd::Ones(1, 1);
      *r_lambda = Eigen::VectorXd::Constant(1, -1.0);
    }
  }
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd&) const override { return Eigen::VectorXd::Ones(1); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
};

}  // namespace hbtrack_tests
