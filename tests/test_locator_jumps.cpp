// A monitor's test function that jumps across zero (a multiplier of a C0 law leaping across the
// unit circle where a contact starts) is located by bisection onto the jump, to 1e-6 of the
// step, in far fewer evaluations than the secant's 1e-12 (each one a Floquet computation), and
// a continuous zero is still located to the secant's precision.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"
#include "straight_branch.hpp"

namespace hbtrack_tests::file_locator_jumps {

using namespace hbtrack;
using Eigen::VectorXd;

namespace {

constexpr double kZero = 4.3;  // where the test functions below change sign (inside a step)

// +0.1 below kZero, -0.7 above (the values of the PD test function on either side of the jump
// on NLvib's two-dof contact example), or tanh((lambda - kZero) / 0.05) when continuous.
class SignMonitor final : public BranchMonitor {
 public:
  explicit SignMonitor(bool jump) : jump_(jump) {}
  std::vector<SpecialPointType> types() const override { return {SpecialPointType::period_doubling}; }
  std::vector<double> test_functions(const BranchPoint& p) override {
    ++evaluations;
    if (jump_) return {p.lambda < kZero ? 0.1 : -0.7};
    return {std::tanh((p.lambda - kZero) / 0.05)};
  }
  int evaluations = 0;

 private:
  bool jump_;
};

struct MonitoredRun {
  ContinuationResult result;
  int evaluations = 0;
  int points = 0;
};

MonitoredRun run(bool jump) {
  StraightBranch problem;
  SignMonitor monitor(jump);
  ContinuationOptions options;
  options.step_max = 0.3;
  const ContinuationResult r =
      continue_within(problem, VectorXd::Zero(1), 0.0, ParameterWindow{0.0, 10.0, 1, false}, options, {}, &monitor);
  return {r, monitor.evaluations, static_cast<int>(r.points.size())};
}

}  // namespace

TEST(LocatorJumps, AJumpIsLocatedToAMillionthOfTheStepByBisection) {
  const MonitoredRun r = run(true);
  ASSERT_EQ(r.result.summary.stop_reason, StopReason::reached_end);
  ASSERT_EQ(r.result.special_points.size(), 1u);
  const SpecialPoint& jump = r.result.special_points[0];
  EXPECT_TRUE(jump.located);
  // The step there is at most step_max = 0.3 long: 1e-6 of it.
  EXPECT_NEAR(jump.lambda, kZero, 0.3e-6);
  // Every accepted point once, then the location: Illinois gains about a decade per four steps
  // on a jump, bisection 3.3, so 1e-6 takes about 20; Illinois to 1e-12 took 51 here (58 on the
  // two-dof contact example, or gave up at its 60).
  const int locating = r.evaluations - r.points;
  EXPECT_GT(locating, 10);
  EXPECT_LE(locating, 30);
}

TEST(LocatorJumps, AContinuousZeroIsStillLocatedToTheSecantsPrecision) {
  const MonitoredRun r = run(false);
  ASSERT_EQ(r.result.special_points.size(), 1u);
  EXPECT_TRUE(r.result.special_points[0].located);
  // 1e-12 of the step in arc, on a function of slope 20 there.
  EXPECT_NEAR(r.result.special_points[0].lambda, kZero, 1e-11);
}

}  // namespace hbtrack_tests::file_locator_jumps
