#pragma once
// Pseudo-arclength continuation one step at a time: predict, correct, accept or halve, bracket
// and locate special points, detect the window's bounds and the branch closing on itself, adapt
// the step. continue_within drives it; a checkpoint saves what state() returns and resume()
// restores it, so a resumed run takes the same steps. Private to src/continuation.
#include <optional>
#include <string>
#include <vector>

#include "scaled_problem.hpp"
#include "special_point_locator.hpp"

namespace hbtrack::continuation_detail {

class ContinuationStepper {
 public:
  // What one call to step() did: the point to accept (none when the step was rejected and
  // halved), and the stop reason when the branch ends there (none to go on).
  struct Outcome {
    std::optional<BranchPoint> point;
    std::optional<StopReason> stop_reason;
  };

  // u_for_scale: a point near the start, for the first scaling of the unknowns.
  ContinuationStepper(ContinuationProblem& problem, const VectorXd& u_for_scale, const ParameterWindow& window,
                      const ContinuationOptions& options, BranchMonitor* monitor);
  ContinuationStepper(const ContinuationStepper&) = delete;  // the locator refers to s_
  ContinuationStepper& operator=(const ContinuationStepper&) = delete;

  // The first point: Newton at fixed lambda_start from u0. False when it fails (the iterations
  // tried are counted in summary()).
  bool start(const VectorXd& u0, double lambda_start, BranchPoint& first);
  // Instead of start(): continue from a state taken by state() (indices go on after its points).
  void resume(const ContinuationState& state);

  Outcome step();

  int points() const { return points_; }  // accepted so far, by this run and the one resumed
  ContinuationState state() const;        // everything the next step depends on
  ContinuationSummary summary() const;    // counters so far (stop_reason and wall_s unset)
  const std::vector<SpecialPoint>& special_points() const { return special_points_; }

 private:
  TestValues test_values(const BranchPoint& p, const Tangent& tan);
  void record_special_points(const VectorXd& y, const BranchPoint& point, const TestValues& current);
  // With window.stop_when_closed: true when the step to y passed the first point, with the copy
  // of it that ends the branch in `closing`.
  bool closes_on_first_point(const VectorXd& y, BranchPoint& closing);
  Outcome emit(BranchPoint point, std::optional<StopReason> stop_reason = std::nullopt);

  Scaled s_;
  const ParameterWindow window_;
  const ContinuationOptions& options_;
  BranchMonitor* monitor_;
  Locator locator_;
  std::vector<std::string> types_{"LP", "BP"};  // then the monitor's
  double direction_ = 1;                        // +1: lambda increasing at the start
  double lambda_end_ = 0, lambda_back_ = 0;     // the bound headed for first ("reached_end") and the other one ("left_range")
  bool corners_ = false;                        // the problem's residual has corners

  // The state a checkpoint saves (ContinuationState).
  int points_ = 0;
  VectorXd x_, x_before_, t_;
  double ds_ = 0;
  bool cut_ = false;     // ds_ was halved since the last accepted point
  double farthest_ = 0;  // scaled distance from the first point, for closure
  TestValues previous_;
  BranchPoint first_point_;
  VectorXd first_scale_;  // the scaling the first point's tangent was computed in
  double first_parameter_scale_ = 0;
  std::vector<SpecialPoint> special_points_;
  ContinuationSummary summary_;

  // The last step rejected for turning too much, to tell a corner from curvature (has_corners).
  // Not in the saved state: a run resumed while one is pending may step differently there.
  struct CornerCandidate {
    double step = 0, turn = 0;
    int points_since = 0;
  } corner_;
};

}  // namespace hbtrack::continuation_detail
