// The continuation engine on piecewise affine residuals (ContinuationProblem::has_corners), the
// structure of a sampled stick-slip or contact law: branches with corners sharper than 90
// degrees, where no point beyond the corner lies on the pseudo-arclength plane, corners that are
// limit points, and a start where plain Newton cycles between two pieces.
#include <gtest/gtest.h>

#include <cmath>

#include "hbtrack/continuation/continuation.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_continuation_corners {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// A piecewise linear function through the knots (x_i, y_i), extended linearly past both ends.
struct PiecewiseLinear {
  std::vector<double> x, y;
  int piece(double at) const {
    int i = 0;
    while (i + 2 < static_cast<int>(x.size()) && at >= x[static_cast<size_t>(i) + 1]) ++i;
    return i;
  }
  double slope(double at) const {
    const auto i = static_cast<size_t>(piece(at));
    return (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  }
  double operator()(double at) const {
    const auto i = static_cast<size_t>(piece(at));
    return y[i] + slope(at) * (at - x[i]);
  }
};

// R(u, lambda) = u - F(lambda): the branch is the graph of F, a zigzag whose corners turn by
// 143 degrees (slopes +3, -3, +3) while lambda keeps increasing, as at the DLFT example's
// pattern changes (100 degrees there).
class Zigzag final : public ContinuationProblem {
 public:
  PiecewiseLinear f{{0.0, 1.0, 2.0, 3.0}, {0.0, 3.0, 0.0, 3.0}};
  int size() const override { return 1; }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jac, VectorXd* r_lambda) override {
    r = VectorXd::Constant(1, u(0) - f(lambda));
    if (jac) {
      *jac = MatrixXd::Ones(1, 1);
      *r_lambda = VectorXd::Constant(1, -f.slope(lambda));
    }
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(1); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
  bool has_corners() const override { return true; }
};

// R(u, lambda) = lambda - G(u), G with slopes +3, -3, +3 (knots u = 1, 1.5): the branch folds at
// both corners, lambda going 0 -> 3 -> 1.5 -> 6, and turns by 143 degrees there. Piecewise affine
// in u, the way a stick-slip law is.
class CornerFolds final : public ContinuationProblem {
 public:
  PiecewiseLinear g{{0.0, 1.0, 1.5, 3.0}, {0.0, 3.0, 1.5, 6.0}};
  int size() const override { return 1; }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jac, VectorXd* r_lambda) override {
    r = VectorXd::Constant(1, lambda - g(u(0)));
    if (jac) {
      *jac = MatrixXd::Constant(1, 1, -g.slope(u(0)));
      *r_lambda = VectorXd::Ones(1);
    }
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(1); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
  bool has_corners() const override { return true; }
};

// R(u, lambda) = S(u) - lambda with S of slope 1 on [-1, 1] and 0.1 outside: plain Newton from
// u = 2 at lambda = 0 cycles between u = -9 and 9 (each step lands on the root of the other
// outer piece's line).
class Saturating final : public ContinuationProblem {
 public:
  explicit Saturating(bool corners) : corners_(corners) {}
  PiecewiseLinear s{{-2.0, -1.0, 1.0, 2.0}, {-1.1, -1.0, 1.0, 1.1}};
  int size() const override { return 1; }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jac, VectorXd* r_lambda) override {
    r = VectorXd::Constant(1, s(u(0)) - lambda);
    if (jac) {
      *jac = MatrixXd::Constant(1, 1, s.slope(u(0)));
      *r_lambda = VectorXd::Constant(1, -1.0);
    }
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(1); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
  bool has_corners() const override { return corners_; }

 private:
  bool corners_;
};

}  // namespace

TEST(ContinuationCorners, StepsOntoCornersSharperThanNinetyDegrees) {
  // Before the corner step the corrector failed at every step size past the first corner
  // (step_size_underflow at lambda = 1).
  Zigzag problem;
  const ContinuationResult r = continue_branch(problem, VectorXd::Zero(1), 0.0, 3.0, ContinuationOptions{});
  ASSERT_EQ(r.summary.stop_reason, StopReason::reached_end);
  EXPECT_GE(r.summary.corners_stepped_over, 2);
  double lambda_before = -1;
  bool at_first = false, at_second = false;
  for (const BranchPoint& p : r.points) {
    EXPECT_LT(std::abs(p.u(0) - problem.f(p.lambda)), 1e-9) << "off the branch at lambda " << p.lambda;
    EXPECT_GT(p.lambda, lambda_before) << "the branch never turns back in lambda";
    lambda_before = p.lambda;
    // The corners are points of the branch, found to the corrector's tolerance (the residual is
    // affine on each side, so the line through the prediction's residual meets zero there).
    at_first = at_first || std::abs(p.lambda - 1.0) < 1e-9;
    at_second = at_second || std::abs(p.lambda - 2.0) < 1e-9;
  }
  EXPECT_TRUE(at_first && at_second);
  for (const SpecialPoint& sp : r.special_points) ADD_FAILURE() << "no special point on a zigzag, got " << sp.type << " at " << sp.lambda;
}

TEST(ContinuationCorners, FollowsLimitPointsAtCorners) {
  // The orientation kept across each corner (the sign of det [R_u R_lambda; t^T]) turns the
  // branch back in lambda at the folds, so u keeps increasing along it; both limit points are
  // the corners themselves.
  CornerFolds problem;
  const ContinuationResult r = continue_branch(problem, VectorXd::Zero(1), 0.0, 6.0, ContinuationOptions{});
  ASSERT_EQ(r.summary.stop_reason, StopReason::reached_end);
  double u_before = -1;
  for (const BranchPoint& p : r.points) {
    EXPECT_LT(std::abs(p.lambda - problem.g(p.u(0))), 1e-9) << "off the branch at u " << p.u(0);
    EXPECT_GT(p.u(0), u_before - 1e-12) << "went back along the branch at lambda " << p.lambda;
    u_before = p.u(0);
  }
  EXPECT_NEAR(r.points.back().u(0), 3.0, 1e-9);
  std::vector<double> folds;
  for (const SpecialPoint& sp : r.special_points) {
    EXPECT_EQ(sp.type, SpecialPointType::limit_point);
    folds.push_back(sp.lambda);
  }
  ASSERT_EQ(folds.size(), 2u);
  EXPECT_NEAR(folds[0], 3.0, 1e-9);
  EXPECT_NEAR(folds[1], 1.5, 1e-9);
}

TEST(ContinuationCorners, DampedNewtonStartsWherePlainNewtonCycles) {
  // At lambda = 0 from u = 2 plain Newton alternates between -9 and 9; a line search on |R|^2
  // takes it to the root u = 0. Only problems with corners get the fallback (a smooth problem
  // keeps plain Newton's answer).
  Saturating smooth(false), piecewise(true);
  VectorXd u = VectorXd::Constant(1, 2.0);
  EXPECT_LT(newton_at_fixed_parameter(smooth, u, 0.0, 1e-12, 30), 0);
  u = VectorXd::Constant(1, 2.0);
  EXPECT_GE(newton_at_fixed_parameter(piecewise, u, 0.0, 1e-12, 30), 0);
  EXPECT_NEAR(u(0), 0.0, 1e-12);
  const ContinuationResult r = continue_branch(piecewise, VectorXd::Constant(1, 2.0), 0.0, 1.05, ContinuationOptions{});
  EXPECT_EQ(r.summary.stop_reason, StopReason::reached_end);
  EXPECT_NEAR(r.points.back().u(0), 1.5, 1e-9);
}

}  // namespace hbtrack_tests::file_continuation_corners
