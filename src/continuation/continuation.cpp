#include "hbtrack/continuation/continuation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "continuation_stepper.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

void ContinuationOptions::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v)) throw std::invalid_argument(std::string("continuation.") + name + ": must be > 0 and finite");
  };
  positive(step, "step");
  positive(step_min, "step_min");
  positive(step_max, "step_max");
  positive(tolerance, "tolerance");
  if (step_min > step) throw std::invalid_argument("continuation.step_min: must be <= step");
  if (step > step_max) throw std::invalid_argument("continuation.step: must be <= step_max");
  if (max_points < 1) throw std::invalid_argument("continuation.max_points: must be >= 1");
  if (max_iterations < 1 || max_iterations > 1000) throw std::invalid_argument("continuation.max_iterations: must be in [1, 1000]");
  if (target_iterations < 1) throw std::invalid_argument("continuation.target_iterations: must be >= 1");
  if (!(max_angle > 0) || max_angle > 3.14159) throw std::invalid_argument("continuation.max_angle: must be in (0, pi]");
  if (!(target_angle > 0) || target_angle > max_angle) throw std::invalid_argument("continuation.target_angle: must be in (0, max_angle]");
  if (!(contraction > 0 && contraction < 1)) throw std::invalid_argument("continuation.contraction: must be in (0, 1)");
  if (!(wall_time_limit >= 0)) throw std::invalid_argument("continuation.wall_time_limit: must be >= 0");
}

bool ContinuationResult::success() const {
  return summary.stop_reason == StopReason::reached_end || summary.stop_reason == StopReason::max_points ||
         summary.stop_reason == StopReason::closed;
}

ContinuationResult continue_branch(ContinuationProblem& problem, const VectorXd& u0, double lambda_start, double lambda_end,
                                   const ContinuationOptions& options, const PointObserver& observer, BranchMonitor* monitor) {
  const ParameterWindow window{std::min(lambda_start, lambda_end), std::max(lambda_start, lambda_end), lambda_end >= lambda_start ? 1 : -1,
                               false};
  return continue_within(problem, u0, lambda_start, window, options, observer, monitor);
}

ContinuationResult continue_within(ContinuationProblem& problem, const VectorXd& u0, double lambda_start, const ParameterWindow& window,
                                   const ContinuationOptions& options, const PointObserver& observer, BranchMonitor* monitor,
                                   const ContinuationRestart& restart) {
  options.validate();
  if (!(window.lambda_min <= lambda_start && lambda_start <= window.lambda_max))
    throw std::invalid_argument("continuation: the start " + std::to_string(lambda_start) + " lies outside the parameter window");
  const auto clock_start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count(); };
  ContinuationResult result;
  continuation_detail::ContinuationStepper stepper(problem, u0, window, options, monitor);
  // The state after the last point passed on whose monitor verdict is settled: what a
  // checkpoint saves (points waiting for a lazy monitor are not in it; a resumed run redoes them).
  ContinuationState settled;
  int passed_on = restart.resume_from ? restart.resume_from->points : 0;
  double last_state_s = -INFINITY;
  auto save_state = [&] {
    last_state_s = elapsed();
    restart.on_state(settled);
  };
  auto finish = [&](StopReason reason) {
    if (restart.on_state && passed_on > 0) save_state();
    result.summary = stepper.summary();
    result.summary.points = passed_on;
    result.summary.stop_reason = reason;
    result.summary.wall_s = elapsed();
    result.special_points = stepper.special_points();
    return result;
  };
  // Passes the points on in order; false when the observer asked to stop (the points after it
  // are dropped, and the state saved is the one before them).
  auto accept = [&](std::vector<BranchPoint> points) {
    for (size_t i = 0; i < points.size(); ++i) {
      result.points.push_back(std::move(points[i]));
      const bool go_on = !observer || observer(result.points.back(), passed_on);
      ++passed_on;
      if (i + 1 == points.size() && stepper.settled()) settled = stepper.state();
      if (!go_on) return false;
    }
    return true;
  };
  // A run that stops passes on the points still waiting for the monitor first.
  auto stop = [&](StopReason reason) {
    if (!stepper.settled() && !accept(stepper.settle())) return finish(StopReason::interrupted);
    return finish(reason);
  };

  if (restart.resume_from) {
    stepper.resume(*restart.resume_from);
    settled = *restart.resume_from;
  } else {
    BranchPoint first;
    if (!stepper.start(u0, lambda_start, first, restart.leave_along)) return finish(StopReason::no_convergence_at_start);
    if (!accept({std::move(first)})) return finish(StopReason::interrupted);
  }
  while (true) {
    if (restart.on_state && elapsed() - last_state_s >= restart.state_interval_s) save_state();
    if (stepper.points() >= options.max_points) return stop(StopReason::max_points);
    if (options.wall_time_limit > 0 && elapsed() > options.wall_time_limit) return stop(StopReason::time_limit);
    continuation_detail::ContinuationStepper::Outcome step = stepper.step();
    if (!accept(std::move(step.points))) return finish(StopReason::interrupted);
    if (step.stop_reason) return finish(*step.stop_reason);
  }
}

}  // namespace hbtrack
