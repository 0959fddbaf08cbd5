#include "hbtrack/runs/failure_advice.hpp"

#include <cstdio>

namespace hbtrack::runs {

namespace {
std::string text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
}  // namespace

std::string continuation_failure_advice(const ContinuationSummary& s, const ContinuationOptions& o, double last_lambda) {
  const std::string at = text(last_lambda);
  const std::string tried = std::to_string(s.newton_iterations) + " Newton iterations, " + std::to_string(s.failed_steps) +
                            " failed steps, " + std::to_string(s.step_halvings) + " step halvings";
  if (s.stop_reason == StopReason::no_convergence_at_start)
    return "Newton from the linear solution and from the solution linearised about rest did not converge at omega = " + at + " (" + tried +
           ", at most " + std::to_string(3 * o.max_iterations) +
           " iterations): start where the response is nearly linear (move continuation.omega_start away from the resonance), "
           "or raise continuation.max_iterations";
  if (s.stop_reason == StopReason::step_size_underflow)
    return "the corrector failed down to continuation.step_min = " + text(o.step_min) + " near omega = " + at + " (" + tried +
           "): a law that is not smooth needs more harmonic_balance.samples or a regularised law (regularized_contact with a "
           "width over a few samples); otherwise lower continuation.step_min or raise continuation.max_iterations";
  if (s.stop_reason == StopReason::step_size_underflow_on_curvature)
    return "the branch turns by more than continuation.max_angle = " + text(o.max_angle) +
           " within continuation.step_min = " + text(o.step_min) + " near omega = " + at + " (" + tried +
           "): raise continuation.max_angle, or resolve the law better (more harmonic_balance.samples, a wider contact width)";
  if (s.stop_reason == StopReason::time_limit)
    return "continuation.wall_time_limit = " + text(o.wall_time_limit) + " s reached at omega = " + at + " (" + tried +
           "): raise it, or resume with `frc --resume`";
  if (s.stop_reason == StopReason::left_range)
    return "the branch turned back and left the range at omega = " + at + ": widen [continuation.omega_start, omega_end]";
  return tried;
}

}  // namespace hbtrack::runs
