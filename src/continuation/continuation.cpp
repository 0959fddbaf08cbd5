#include "hbtrack/continuation/continuation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "corner_step.hpp"
#include "fixed_parameter_newton.hpp"
#include "scaled_problem.hpp"

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
  if (predictor != "tangent" && predictor != "secant")
    throw std::invalid_argument("continuation.predictor: must be tangent or secant, got '" + predictor + "'");
  if (corrector != "pseudo_arclength" && corrector != "hypersphere")
    throw std::invalid_argument("continuation.corrector: must be pseudo_arclength or hypersphere, got '" + corrector + "'");
  if (!(contraction > 0 && contraction < 1)) throw std::invalid_argument("continuation.contraction: must be in (0, 1)");
  if (!(wall_time_limit >= 0)) throw std::invalid_argument("continuation.wall_time_limit: must be >= 0");
}

bool ContinuationResult::success() const {
  return summary.stop_reason == "reached_end" || summary.stop_reason == "max_points" || summary.stop_reason == "closed";
}

namespace {

using continuation_detail::inf_norm;
using continuation_detail::Scaled;
using continuation_detail::Tangent;

// Test-function values at a point: engine's LP and BP first, then the monitor's.
struct TestValues {
  std::vector<double> values;
  double bp_log_det = 0;  // BP is stored relative to this, so values stay in range
};

// Zero of one test function between two accepted points, by the Illinois variant of the secant
// method on the pseudo-arclength coordinate s along the tangent `t0` at the first point.
struct Locator {
  Scaled& s;
  const ContinuationOptions& options;
  BranchMonitor* monitor;

  // Corrected point at plane coordinate `arc` from x0; fills its tangent. False if Newton fails.
  bool point_at(const VectorXd& x0, const VectorXd& t0, double arc, VectorXd& y, Tangent& tan) {
    y = x0 + arc * t0;
    int iterations = 0;
    if (!s.correct(y, x0, t0, arc, false, options, iterations)) return false;
    tan = s.tangent(t0);
    return true;
  }

  double value(size_t which, const VectorXd& y, const Tangent& tan, double reference_log_det) {
    if (which == 0) return tan.t(s.m);
    if (which == 1) return tan.det_sign * std::exp(std::min(tan.log_det - reference_log_det, 600.0));
    BranchPoint p{s.unknowns(y), s.parameter(y), tan.t, 0, 0};
    return monitor->test_functions(p)[which - 2];
  }

  // Returns true and the located point when the iteration converged.
  bool locate(size_t which, const VectorXd& x0, const VectorXd& t0, double f0, const VectorXd& x1, double f1,
              double reference_log_det, VectorXd& y_out, Tangent& tan_out) {
    double a = 0, fa = f0, b = t0.dot(x1 - x0), fb = f1;
    const double span = b;
    int side = 0;
    for (int it = 0; it < 60; ++it) {
      double c = b - fb * (b - a) / (fb - fa);
      // Near the zero the test function is roundoff, and the secant may leave the bracket:
      // bisect instead.
      if (!(c > a && c < b)) c = 0.5 * (a + b);
      VectorXd y;
      Tangent tan;
      if (!point_at(x0, t0, c, y, tan)) return false;
      const double fc = value(which, y, tan, reference_log_det);
      y_out = y;
      tan_out = tan;
      if (fc == 0.0 || std::abs(b - a) <= 1e-12 * span) return true;
      if ((fc > 0) == (fb > 0)) {
        b = c, fb = fc;
        if (side == -1) fa *= 0.5;  // Illinois: halve the stale end so it cannot stall
        side = -1;
      } else {
        a = c, fa = fc;
        if (side == 1) fb *= 0.5;
        side = 1;
      }
      if (std::abs(b - a) <= 1e-12 * span) return true;
    }
    return false;
  }
};

}  // namespace

ContinuationResult continue_branch(ContinuationProblem& problem, const VectorXd& u0, double lambda_start,
                                   double lambda_end, const ContinuationOptions& options, const PointObserver& observer,
                                   BranchMonitor* monitor) {
  const ParameterWindow window{std::min(lambda_start, lambda_end), std::max(lambda_start, lambda_end),
                               lambda_end >= lambda_start ? 1 : -1, false};
  return continue_within(problem, u0, lambda_start, window, options, observer, monitor);
}

ContinuationResult continue_within(ContinuationProblem& problem, const VectorXd& u0, double lambda_start,
                                   const ParameterWindow& window, const ContinuationOptions& options,
                                   const PointObserver& observer, BranchMonitor* monitor, const ContinuationRestart& restart) {
  options.validate();
  if (!(window.lambda_min <= lambda_start && lambda_start <= window.lambda_max))
    throw std::invalid_argument("continuation: the start " + std::to_string(lambda_start) + " lies outside the parameter window");
  const auto clock_start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count(); };
  ContinuationResult result;
  ContinuationSummary& summary = result.summary;
  Scaled s{problem, problem.unknown_scale(u0), problem.parameter_scale(), problem.residual_scale(), problem.size(), {}, {}, {}};
  const int m = s.m;
  const double direction = window.direction >= 0 ? 1.0 : -1.0;
  // The bound the branch heads for first ("reached_end") and the other one ("left_range").
  const double lambda_end = direction > 0 ? window.lambda_max : window.lambda_min;
  const double lambda_back = direction > 0 ? window.lambda_min : window.lambda_max;
  const bool hypersphere = options.corrector == "hypersphere";
  std::vector<std::string> types{"LP", "BP"};
  if (monitor)
    for (const auto& t : monitor->types()) types.push_back(t);
  Locator locator{s, options, monitor};

  // A resumed run numbers its points after those of the state it resumes from.
  const int points_before = restart.resume_from ? restart.resume_from->points : 0;
  auto accepted_points = [&] { return points_before + static_cast<int>(result.points.size()); };
  auto finish = [&](const std::string& reason) {
    summary.stop_reason = reason;
    summary.points = accepted_points();
    summary.jacobian_evaluations = s.jacobian_evaluations;
    summary.factorizations = s.factorizations;
    summary.residual_evaluations = s.residual_evaluations;
    summary.chord_iterations = s.chord_iterations;
    summary.newton_iterations += s.newton_iterations;
    summary.wall_s = elapsed();
    return result;
  };
  auto test_values = [&](const BranchPoint& p, const Tangent& tan) {
    TestValues v;
    v.bp_log_det = tan.log_det;
    v.values = {tan.t(m), static_cast<double>(tan.det_sign)};
    if (monitor)
      for (double f : monitor->test_functions(p)) v.values.push_back(f);
    return v;
  };
  auto accept = [&](BranchPoint p) {
    result.points.push_back(std::move(p));
    const int index = accepted_points() - 1;
    return !observer || observer(result.points.back(), index);
  };

  VectorXd x, t;
  double ds = options.step;
  // The last step rejected for turning too much, to tell a corner from curvature (has_corners).
  struct CornerCandidate {
    double step = 0, turn = 0;
    int points_since = 0;
  } corner;
  const bool corners = problem.has_corners();
  double farthest = 0;      // scaled distance from the first point, for closure
  BranchPoint first_point;  // for closure
  VectorXd first_scale;     // the scaling the first point's tangent was computed in
  double first_parameter_scale = s.sl;
  VectorXd x_prev_prev;     // for the secant predictor
  TestValues previous;
  if (const ContinuationState* state = restart.resume_from) {
    // Resume: restore every variable the loop below reads, as the state recorded them.
    if (state->x.size() != m + 1 || state->tangent.size() != m + 1 || state->unknown_scale.size() != m)
      throw std::invalid_argument("continuation: the state to resume from has " + std::to_string(state->x.size() - 1) +
                                  " unknowns, the problem " + std::to_string(m));
    x = state->x;
    x_prev_prev = state->x_before;
    t = state->tangent;
    s.su = state->unknown_scale;
    ds = state->step;
    farthest = state->farthest;
    previous.values = state->test_values;
    previous.bp_log_det = state->bp_log_det;
    first_point = state->first;
    first_scale = state->first_scale;
    first_parameter_scale = state->first_parameter_scale;
    result.special_points = state->special_points;
    summary = state->summary;
    s.jacobian_evaluations = summary.jacobian_evaluations;
    s.factorizations = summary.factorizations;
    s.residual_evaluations = summary.residual_evaluations;
    s.chord_iterations = summary.chord_iterations;
  } else {
    // First point: Newton at fixed lambda_start.
    VectorXd u = u0;
    int used = 0;
    const int first_iterations = continuation_detail::fixed_parameter_newton(problem, u, lambda_start, options.tolerance, 3 * options.max_iterations, used);
    if (first_iterations < 0) {
      summary.newton_iterations += used;  // what was tried, for the failure message
      ++summary.failed_steps;
      return finish("no_convergence_at_start");
    }
    summary.newton_iterations += first_iterations;
    s.su = problem.unknown_scale(u);
    x = s.pack(u, lambda_start);
    s.evaluate(x);
    VectorXd lambda_axis = VectorXd::Zero(m + 1);
    lambda_axis(m) = direction;
    Tangent tan = s.tangent(lambda_axis);
    if (tan.t(m) * direction < 0) tan.t = -tan.t;
    t = tan.t;
    first_point = BranchPoint{u, lambda_start, t, first_iterations, 0.0};
    previous = test_values(first_point, tan);
    first_scale = s.su;
    if (!accept(first_point)) return finish("interrupted");
  }
  // The state between two steps, for restart.on_state; counters as finish() would report them.
  auto state_now = [&] {
    ContinuationState state{accepted_points(), x, x_prev_prev, t, s.su, ds, farthest, previous.values, previous.bp_log_det,
                            first_point, first_scale, first_parameter_scale, result.special_points, summary};
    state.summary.jacobian_evaluations = s.jacobian_evaluations;
    state.summary.factorizations = s.factorizations;
    state.summary.residual_evaluations = s.residual_evaluations;
    state.summary.chord_iterations = s.chord_iterations;
    state.summary.newton_iterations += s.newton_iterations;
    state.summary.points = accepted_points();
    return state;
  };

  while (true) {
    if (restart.on_state) restart.on_state(state_now());
    if (accepted_points() >= options.max_points) return finish("max_points");
    if (options.wall_time_limit > 0 && elapsed() > options.wall_time_limit) return finish("time_limit");

    VectorXd direction_vec = t;
    if (options.predictor == "secant" && x_prev_prev.size() == m + 1) {
      direction_vec = x - x_prev_prev;
      direction_vec.normalize();
    }
    const VectorXd prediction = x + ds * direction_vec;
    VectorXd y = prediction;
    int iterations = 0;
    const int chords_before = s.chord_iterations;
    const bool converged = s.correct(y, x, direction_vec, ds, hypersphere, options, iterations);
    // The sign of the bordered determinant at the last point: test_values stores it as the BP
    // test function, values[1].
    const int det_sign = static_cast<int>(previous.values[1]);
    Tangent tan_new;
    // On a piecewise smooth branch a corrector fails where the branch turns by more than 90
    // degrees at a corner: step onto the corner and leave it along the next piece instead.
    const bool onto_corner = !converged && corners && step_to_corner(s, x, direction_vec, det_sign, ds, options, y, tan_new, iterations);

    // Reject a corrector that did not converge, went back along the branch, jumped away from
    // the prediction or turned too sharply; at the smallest step a corner is real (a
    // nonsmooth law kinks the branch): go through it.
    const bool smallest_step = ds <= 2 * options.step_min;
    bool accepted = onto_corner || (converged && (y - x).dot(t) > 0 && (smallest_step || (y - prediction).norm() <= ds));
    bool through_corner = false;
    if (accepted && !onto_corner) {
      // Through a corner (smallest step) the branch goes on the way the step went: oriented by
      // the old tangent, a turn sharper than 90 degrees would send it back along itself.
      tan_new = s.tangent(smallest_step ? VectorXd((y - x).normalized()) : t);
      const double turn = std::acos(std::clamp(t.dot(tan_new.t), -1.0, 1.0));
      accepted = smallest_step || turn <= options.max_angle;
      // A smooth branch turns in proportion to the step; a corner of a sampled C0 law (or a fold
      // narrower than a time sample) turns as much at half the step. Once seen, go through it
      // at this step instead of halving down to step_min and growing back over dozens of points.
      if (!accepted && corners) {
        if (corner.turn > 0 && ds <= 0.5 * corner.step && turn >= 0.75 * corner.turn) {
          tan_new = s.tangent(VectorXd((y - x).normalized()));
          accepted = through_corner = true;
        } else {
          corner = {ds, turn, 0};
        }
      }
      // Along a branch the sign of det [R_u R_lambda; t^T] changes only at a branch point. Where
      // a piecewise smooth branch folds back close to itself, a long step can land on the part
      // coming back, the turn looking small: that point's tangent, oriented along the old one,
      // then has the other sign. Shorter steps follow the branch round; at the smallest step a
      // change of sign is a branch point.
      if (accepted && corners && !smallest_step && tan_new.det_sign != det_sign) accepted = through_corner = false;
    }
    if (!accepted) {
      if (!converged) ++summary.failed_steps;
      ++summary.step_halvings;
      ds *= 0.5;
      if (ds < options.step_min) return finish(converged ? "step_size_underflow_on_curvature" : "step_size_underflow");
      continue;
    }
    if (through_corner || onto_corner) ++summary.corners_stepped_over;

    const double arc = (y - x).norm();
    BranchPoint point{s.unknowns(y), s.parameter(y), tan_new.t, iterations, arc};
    const TestValues current = test_values(point, tan_new);
    // Bracket and locate special points between x and y.
    const int index_new = accepted_points();
    for (size_t k = 0; k < types.size(); ++k) {
      const double f0 = k == 1 ? previous.values[1] : previous.values[k];
      const double f1 = k == 1 ? current.values[1] * std::exp(std::min(current.bp_log_det - previous.bp_log_det, 600.0))
                               : current.values[k];
      if (!(f0 * f1 < 0)) continue;
      SpecialPoint sp{types[k], index_new, false, point.lambda, point.u, point.tangent, ""};
      VectorXd located;
      Tangent located_tan;
      if (options.locate && locator.locate(k, x, t, f0, y, f1, previous.bp_log_det, located, located_tan)) {
        const double along = t.dot(located - x) / std::max(t.dot(y - x), 1e-300);
        sp = {types[k], along < 0.5 ? index_new - 1 : index_new, true, s.parameter(located), s.unknowns(located), located_tan.t, ""};
      } else if (types[k] == "LP") {
        // Unlocated: the point where lambda is extreme.
        const bool was_rising = t(m) > 0;
        if (was_rising ? s.parameter(x) > s.parameter(y) : s.parameter(x) < s.parameter(y))
          sp = {types[k], index_new - 1, false, s.parameter(x), s.unknowns(x), t, ""};
      }
      if (k >= 2) {
        sp.type = monitor->classify(types[k], BranchPoint{sp.u, sp.lambda, sp.tangent, 0, 0}, sp.located, sp.decided_by);
        // Two test functions may flip for one crossing (a nearly real pair): record it once.
        const auto same = [&](const SpecialPoint& q) { return q.type == sp.type && q.index == sp.index; };
        if (sp.type.empty() || std::any_of(result.special_points.begin(), result.special_points.end(), same)) continue;
      }
      result.special_points.push_back(sp);
    }
    previous = current;
    x_prev_prev = x;
    x = y;
    t = tan_new.t;
    const double lambda = point.lambda;
    // Crossing a bound of the window: land exactly on it, interpolating the last step.
    const bool beyond_end = (lambda - lambda_end) * direction >= 0;
    const bool beyond_back = (lambda - lambda_back) * direction < 0;
    if (beyond_end || beyond_back) {
      const double bound = beyond_end ? lambda_end : lambda_back;
      const std::string reason = beyond_end ? "reached_end" : "left_range";
      const double lam_prev = s.parameter(x_prev_prev);
      const double f = (bound - lam_prev) / (lambda - lam_prev);
      VectorXd u_end = s.unknowns(x_prev_prev + f * (x - x_prev_prev));
      const int it = newton_at_fixed_parameter(problem, u_end, bound, options.tolerance, options.max_iterations);
      if (it >= 0) {
        summary.newton_iterations += it;
        if (!accept({u_end, bound, t, it, arc * f})) return finish("interrupted");
        return finish(reason);
      }
      if (!accept(point)) return finish("interrupted");
      return finish(reason);
    }
    // Back at the first point (an isolated branch, a closed tracking curve): the step's chord
    // passes within a quarter step of it after the branch went more than two steps away from
    // it (a loop only three steps across, as the tracked fold of a law narrower than a sample
    // draws, went round 290 times under the former four). A closed curve ends on a copy of its
    // first point.
    if (window.stop_when_closed) {
      const VectorXd first_x = s.pack(first_point.u, first_point.lambda);
      const VectorXd chord = y - x_prev_prev;
      const double length = chord.norm();
      farthest = std::max(farthest, (y - first_x).norm());
      const double along = length > 0 ? (first_x - x_prev_prev).dot(chord) / length : -1.0;
      const double off = (first_x - x_prev_prev - along * chord / std::max(length, 1e-300)).norm();
      // A loop arrives with the orientation it left with; a branch that turned back on itself
      // (a sharp corner taken at the smallest step) passes the start going the other way.
      const VectorXd first_t = s.pack(first_point.u + first_point.tangent.head(m).cwiseProduct(first_scale),
                                      first_point.lambda + first_point.tangent(m) * first_parameter_scale) -
                               first_x;
      const bool same_orientation = first_t.dot(t) > 0;
      if (farthest > 2 * length && along >= 0 && along <= length && off <= 0.25 * length && same_orientation) {
        BranchPoint closing = first_point;
        closing.step = (first_x - x_prev_prev).norm();
        if (!accept(closing)) return finish("interrupted");
        return finish("closed");
      }
    }
    if (!accept(point)) return finish("interrupted");

    s.rescale(s.unknowns(x), {&x, &x_prev_prev}, t);
    // A chord step counts half: it gains about half the digits of a Newton step near the
    // solution (linear against quadratic convergence) at a fraction of the cost.
    const double work = iterations - 0.5 * (s.chord_iterations - chords_before);
    const double factor = work == 0 ? 1.5 : std::clamp(options.target_iterations / work, 0.5, 1.5);
    // Past a corner the branch is as smooth as before it: back to the step that met it.
    ds = std::min(through_corner ? std::max(ds * factor, corner.step) : ds * factor, options.step_max);
    // A remembered turn only stands for the corner just ahead.
    if (through_corner || ++corner.points_since > 4) corner = {};
  }
}

}  // namespace hbtrack
