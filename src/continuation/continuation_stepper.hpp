#pragma once
// Pseudo-arclength continuation one step at a time: predict, correct, accept or halve, bracket
// and locate special points, detect the window's bounds and the branch closing on itself, adapt
// the step. continue_within drives it; a checkpoint saves what state() returns and resume()
// restores it, so a resumed run takes the same steps. Private to src/continuation.
#include <optional>
#include <string>
#include <vector>

#include "monitor_schedule.hpp"
#include "scaled_problem.hpp"
#include "special_point_locator.hpp"

namespace hbtrack::continuation_detail {

class ContinuationStepper {
 public:
  // What one call to step() did: the points to pass on, in order (none when the step was
  // rejected and halved, or when its point waits for a lazy monitor's next evaluation; several
  // when that evaluation settles the points before it), and the stop reason when the branch
  // ends there (none to go on).
  struct Outcome {
    std::vector<BranchPoint> points;
    std::optional<StopReason> stop_reason;
  };

  // u_for_scale: a point near the start, for the first scaling of the unknowns.
  ContinuationStepper(ContinuationProblem& problem, const VectorXd& u_for_scale, const ParameterWindow& window,
                      const ContinuationOptions& options, BranchMonitor* monitor);
  ContinuationStepper(const ContinuationStepper&) = delete;  // the locator refers to s_
  ContinuationStepper& operator=(const ContinuationStepper&) = delete;

  // The first point: Newton at fixed lambda_start from u0. False when it fails (the iterations
  // tried are counted in summary()).
  // leave_along: orients the first tangent (ContinuationRestart::leave_along), nullptr: the window.
  bool start(const VectorXd& u0, double lambda_start, BranchPoint& first, const VectorXd* leave_along = nullptr);
  // Instead of start(): continue from a state taken by state() (indices go on after its points).
  void resume(const ContinuationState& state);

  Outcome step();
  // The points still waiting for a lazy monitor, settled by evaluating it at the last of them
  // (a run that stops passes them on before it saves its state).
  std::vector<BranchPoint> settle();
  bool settled() const { return pending_.empty(); }

  int points() const { return points_; }  // accepted so far, by this run and the one resumed
  // Everything the next step depends on; meaningful when settled() (a checkpoint is taken then).
  ContinuationState state() const;
  ContinuationSummary summary() const;  // counters so far (stop_reason and wall_s unset)
  const std::vector<SpecialPoint>& special_points() const { return special_points_; }

 private:
  // The engine's test values at a point (LP: the tangent's parameter component, BP: the
  // bordered determinant's sign); the monitor's are added by evaluate_monitor.
  TestValues engine_test_values(const Tangent& tan) const;
  void evaluate_monitor(MonitoredPoint& p);
  // LP and BP between the last point and the new one y.
  void record_engine_special_points(const VectorXd& y, const BranchPoint& point, const TestValues& current);
  // The monitor's special points between two points it evaluated.
  void record_monitor_special_points(const MonitoredPoint& a, const MonitoredPoint& b);
  // The evaluated point `now` settles the pending points before it: when its test functions'
  // signs or verdict differ from the last evaluated point's, every pending point is evaluated;
  // then the monitor's special points are recorded step by step. Returns the settled points.
  std::vector<BranchPoint> settle_with(MonitoredPoint now);
  // v (scaled coordinates or a tangent, in the unknown scale su_then) in the current scale.
  VectorXd in_current_scale(const VectorXd& v, const VectorXd& su_then, bool normalize) const;
  // With window.stop_when_closed: true when the step from `start` to y passed the first point
  // (t: the tangent at y), with the copy of it that ends the branch in `closing`.
  bool closes_on_first_point(const VectorXd& start, const VectorXd& y, const VectorXd& t, BranchPoint& closing);

  Scaled s_;
  const ParameterWindow window_;
  const ContinuationOptions& options_;
  BranchMonitor* monitor_;
  Locator locator_;
  std::vector<SpecialPointType> types_{SpecialPointType::limit_point, SpecialPointType::branch_point};  // then the monitor's
  double direction_ = 1;                     // +1: lambda increasing at the start
  double lambda_end_ = 0, lambda_back_ = 0;  // the bound headed for first ("reached_end") and the other one ("left_range")
  bool corners_ = false;                     // the problem's residual has corners
  bool lazy_ = false;                        // the monitor may skip points

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
  // A lazy monitor's: its last evaluations, the last point it evaluated, the points accepted
  // after it (waiting), and the arc length travelled (positions of those points).
  MonitorHistory history_;
  MonitoredPoint last_monitored_;
  std::vector<MonitoredPoint> pending_;
  double arc_ = 0;

  // The last step rejected for turning too much, to tell a corner from curvature (has_corners).
  // Not in the saved state: a run resumed while one is pending may step differently there.
  struct CornerCandidate {
    double step = 0, turn = 0;
    int points_since = 0;
  } corner_;
};

}  // namespace hbtrack::continuation_detail
