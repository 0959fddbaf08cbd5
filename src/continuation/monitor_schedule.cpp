#include "monitor_schedule.hpp"

#include <cmath>

namespace hbtrack::continuation_detail {

namespace {
// Linear extrapolation of f through (a, fa), (b, fb): the distance past b where it reaches zero
// when it heads there, infinity otherwise.
double distance_to_zero(double a, double fa, double b, double fb) {
  if (!(fa * fb > 0) || !(std::abs(fb) < std::abs(fa)) || !(b > a)) return INFINITY;
  return (b - a) * std::abs(fb) / (std::abs(fa) - std::abs(fb));
}
}  // namespace

bool monitor_due(const MonitorHistory& history, double arc, const std::vector<double>& engine_before, const std::vector<double>& engine_now,
                 double step, double turn) {
  if (history.before.empty() || history.last.size() != history.before.size()) return true;
  if (history.points_since >= kMaxSkippedPoints || !(history.turn_since + turn < kTurnPerEvaluation)) return true;
  for (size_t k = 2; k < history.last.size(); ++k) {
    const double d = distance_to_zero(history.before_arc, history.before[k], history.last_arc, history.last[k]);
    if (arc - history.last_arc >= 0.5 * d) return true;
  }
  // The fold test (the tangent's parameter component) and the bordered determinant's sign.
  for (size_t k = 0; k < 2 && k < engine_before.size() && k < engine_now.size(); ++k)
    if (!(engine_before[k] * engine_now[k] > 0)) return true;
  return !engine_before.empty() && !engine_now.empty() && distance_to_zero(0, engine_before[0], step, engine_now[0]) <= 1.5 * step;
}

}  // namespace hbtrack::continuation_detail
