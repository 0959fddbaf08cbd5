// A costly monitor evaluated only where its verdict can change (BranchMonitor::may_skip_points):
// the engine passes the points it skipped on once an evaluated point settles them, evaluates
// every point between two that disagree and locates the change there, and a run resumed from
// a saved state repeats the whole run exactly. On a straight branch with a test function that
// is flat away from its zero, so that only the bounded interval and the disagreement find it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"
#include "straight_branch.hpp"

namespace hbtrack_tests::file_lazy_monitor {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Its test function changes sign at lambda = kChange within a width of 1e-3 and is flat (+-1 to
// 1e-300) a step away: no extrapolation sees the zero coming.
constexpr double kChange = 4.3;

class StepMonitor final : public BranchMonitor {
 public:
  explicit StepMonitor(bool lazy) : lazy_(lazy) {}
  std::vector<SpecialPointType> types() const override { return {SpecialPointType::period_doubling}; }
  std::vector<double> test_functions(const BranchPoint& p) override {
    ++evaluations;
    return {std::tanh((p.lambda - kChange) / 1e-3)};
  }
  bool may_skip_points() const override { return lazy_; }
  int verdict(const BranchPoint& p) override { return p.lambda > kChange ? 1 : 0; }
  int evaluations = 0;

 private:
  bool lazy_;
};

ContinuationOptions straight_options() {
  ContinuationOptions o;
  o.step_max = 0.3;
  return o;
}

const ParameterWindow kWindow{0.0, 10.0, 1, false};

ContinuationResult run(StepMonitor& monitor, const PointObserver& observer = {}, const ContinuationRestart& restart = {}) {
  StraightBranch problem;
  return continue_within(problem, VectorXd::Zero(1), 0.0, kWindow, straight_options(), observer, &monitor, restart);
}

}  // namespace

TEST(LazyMonitor, LocatesTheChangeAsAnEveryPointMonitorDoesWithFewerEvaluations) {
  StepMonitor every(false), lazy(true);
  const ContinuationResult reference = run(every);
  std::vector<int> indices;
  std::vector<BranchPoint> seen;
  const ContinuationResult r = run(lazy, [&](const BranchPoint& p, int index) {
    indices.push_back(index);
    seen.push_back(p);
    return true;
  });
  ASSERT_EQ(r.summary.stop_reason, StopReason::reached_end);
  ASSERT_EQ(reference.special_points.size(), 1u);
  ASSERT_EQ(r.special_points.size(), 1u);
  // Both locate the zero of tanh by the secant to 1e-12 of the bracket: the same point to round-off.
  EXPECT_TRUE(r.special_points[0].located);
  EXPECT_NEAR(r.special_points[0].lambda, kChange, 1e-9);
  EXPECT_NEAR(r.special_points[0].lambda, reference.special_points[0].lambda, 1e-9);
  // Every point passed on once, in order, the last one at the end of the window.
  ASSERT_EQ(indices.size(), r.points.size());
  for (size_t i = 0; i < indices.size(); ++i) EXPECT_EQ(indices[i], static_cast<int>(i));
  EXPECT_EQ(seen.back().lambda, 10.0);
  EXPECT_EQ(r.summary.points, static_cast<int>(r.points.size()));
  // A skipped point lies on the side of the change of the evaluated point before it (their
  // verdicts agree); the points around the change were evaluated.
  int skipped = 0;
  for (size_t i = 1; i < seen.size(); ++i) {
    if (seen[i].monitored) continue;
    ++skipped;
    size_t j = i;
    while (!seen[j].monitored) --j;
    EXPECT_EQ(seen[i].lambda > kChange, seen[j].lambda > kChange) << i;
  }
  EXPECT_GT(skipped, 0);
  const int bracket = r.special_points[0].index;
  EXPECT_TRUE(seen[static_cast<size_t>(bracket)].monitored);
  // Fewer evaluations, the locator's included (the step's own test functions are flat there).
  EXPECT_LT(lazy.evaluations, every.evaluations);
}

TEST(LazyMonitor, AResumedRunRepeatsTheWholeRunExactly) {
  StepMonitor whole_monitor(true);
  std::vector<ContinuationState> states;
  ContinuationRestart saving;
  saving.on_state = [&](const ContinuationState& s) { states.push_back(s); };
  saving.state_interval_s = 0;  // a state between every two steps: at the last settled point
  const ContinuationResult whole = run(whole_monitor, {}, saving);
  ASSERT_EQ(whole.summary.stop_reason, StopReason::reached_end);
  ASSERT_EQ(whole.special_points.size(), 1u);
  // Every state a checkpoint could hold, before the change and after it.
  int resumed_runs = 0;
  for (const ContinuationState& state : states) {
    if (state.points >= whole.summary.points) continue;
    StepMonitor monitor(true);
    ContinuationRestart resuming;
    resuming.resume_from = &state;
    const ContinuationResult rest = run(monitor, {}, resuming);
    ASSERT_EQ(rest.points.size() + static_cast<size_t>(state.points), whole.points.size()) << state.points;
    for (size_t i = 0; i < rest.points.size(); ++i) {
      const BranchPoint& w = whole.points[i + static_cast<size_t>(state.points)];
      EXPECT_EQ(rest.points[i].lambda, w.lambda) << state.points << " " << i;
      EXPECT_EQ(rest.points[i].monitored, w.monitored) << state.points << " " << i;
    }
    ASSERT_EQ(rest.special_points.size(), 1u) << state.points;
    EXPECT_EQ(rest.special_points[0].lambda, whole.special_points[0].lambda);
    EXPECT_EQ(rest.special_points[0].index, whole.special_points[0].index);
    ++resumed_runs;
  }
  EXPECT_GT(resumed_runs, 5);
}

TEST(LazyMonitor, AnInterruptedRunSavesAStateItsResumptionCompletesExactly) {
  StepMonitor whole_monitor(true);
  const ContinuationResult whole = run(whole_monitor);
  for (int stop_at = 1; stop_at < whole.summary.points - 1; ++stop_at) {
    StepMonitor monitor(true);
    ContinuationState last;
    ContinuationRestart saving;
    saving.on_state = [&](const ContinuationState& s) { last = s; };
    const ContinuationResult stopped = run(
        monitor, [&](const BranchPoint&, int index) { return index < stop_at; }, saving);
    ASSERT_EQ(stopped.summary.stop_reason, StopReason::interrupted);
    // The saved state never runs ahead of the points passed on (the rest are redone).
    ASSERT_LE(last.points, static_cast<int>(stopped.points.size())) << stop_at;
    StepMonitor resumed_monitor(true);
    ContinuationRestart resuming;
    resuming.resume_from = &last;
    const ContinuationResult rest = run(resumed_monitor, {}, resuming);
    ASSERT_EQ(rest.points.size() + static_cast<size_t>(last.points), whole.points.size()) << stop_at;
    EXPECT_EQ(rest.points.back().lambda, whole.points.back().lambda);
    ASSERT_EQ(rest.special_points.size(), 1u);
    EXPECT_EQ(rest.special_points[0].lambda, whole.special_points[0].lambda);
  }
}

}  // namespace hbtrack_tests::file_lazy_monitor
