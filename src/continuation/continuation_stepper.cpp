#include "continuation_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "corner_step.hpp"
#include "fixed_parameter_newton.hpp"
#include "step_control.hpp"

namespace hbtrack::continuation_detail {

ContinuationStepper::ContinuationStepper(ContinuationProblem& problem, const VectorXd& u_for_scale, const ParameterWindow& window,
                                         const ContinuationOptions& options, BranchMonitor* monitor)
    : s_{problem, problem.unknown_scale(u_for_scale), problem.parameter_scale(), problem.residual_scale(), problem.size(), {}, {}, {}},
      window_(window),
      options_(options),
      monitor_(monitor),
      locator_{s_, options_, monitor_},
      direction_(window.direction >= 0 ? 1.0 : -1.0),
      lambda_end_(direction_ > 0 ? window.lambda_max : window.lambda_min),
      lambda_back_(direction_ > 0 ? window.lambda_min : window.lambda_max),
      corners_(problem.has_corners()),
      ds_(options.step),
      first_parameter_scale_(s_.sl) {
  if (monitor)
    for (const auto& t : monitor->types()) types_.push_back(t);
}

bool ContinuationStepper::start(const VectorXd& u0, double lambda_start, BranchPoint& first) {
  VectorXd u = u0;
  int used = 0;
  const int iterations = fixed_parameter_newton(s_.problem, u, lambda_start, options_.tolerance, 3 * options_.max_iterations, used);
  if (iterations < 0) {
    summary_.newton_iterations += used;  // what was tried, for the failure message
    ++summary_.failed_steps;
    return false;
  }
  summary_.newton_iterations += iterations;
  s_.su = s_.problem.unknown_scale(u);
  x_ = s_.pack(u, lambda_start);
  s_.evaluate(x_);
  VectorXd lambda_axis = VectorXd::Zero(s_.m + 1);
  lambda_axis(s_.m) = direction_;
  Tangent tan = s_.tangent(lambda_axis);
  if (tan.t(s_.m) * direction_ < 0) tan.t = -tan.t;
  t_ = tan.t;
  first_point_ = BranchPoint{u, lambda_start, t_, iterations, 0.0};
  previous_ = test_values(first_point_, tan);
  first_scale_ = s_.su;
  first = first_point_;
  ++points_;
  return true;
}

void ContinuationStepper::resume(const ContinuationState& state) {
  const int m = s_.m;
  if (state.x.size() != m + 1 || state.tangent.size() != m + 1 || state.unknown_scale.size() != m)
    throw std::invalid_argument("continuation: the state to resume from has " + std::to_string(state.x.size() - 1) +
                                " unknowns, the problem " + std::to_string(m));
  points_ = state.points;
  x_ = state.x;
  x_before_ = state.x_before;
  t_ = state.tangent;
  s_.su = state.unknown_scale;
  ds_ = state.step;
  cut_ = state.step_cut;
  farthest_ = state.farthest;
  previous_.values = state.test_values;
  previous_.bp_log_det = state.bp_log_det;
  first_point_ = state.first;
  first_scale_ = state.first_scale;
  first_parameter_scale_ = state.first_parameter_scale;
  special_points_ = state.special_points;
  summary_ = state.summary;
  s_.jacobian_evaluations = summary_.jacobian_evaluations;
  s_.factorizations = summary_.factorizations;
  s_.residual_evaluations = summary_.residual_evaluations;
  s_.chord_iterations = summary_.chord_iterations;
}

ContinuationSummary ContinuationStepper::summary() const {
  ContinuationSummary out = summary_;
  out.jacobian_evaluations = s_.jacobian_evaluations;
  out.factorizations = s_.factorizations;
  out.residual_evaluations = s_.residual_evaluations;
  out.chord_iterations = s_.chord_iterations;
  out.newton_iterations += s_.newton_iterations;
  out.points = points_;
  return out;
}

ContinuationState ContinuationStepper::state() const {
  return ContinuationState{points_,
                           x_,
                           x_before_,
                           t_,
                           s_.su,
                           ds_,
                           cut_,
                           farthest_,
                           previous_.values,
                           previous_.bp_log_det,
                           first_point_,
                           first_scale_,
                           first_parameter_scale_,
                           special_points_,
                           summary()};
}

TestValues ContinuationStepper::test_values(const BranchPoint& p, const Tangent& tan) {
  TestValues v;
  v.bp_log_det = tan.log_det;
  v.values = {tan.t(s_.m), static_cast<double>(tan.det_sign)};
  if (monitor_)
    for (double f : monitor_->test_functions(p)) v.values.push_back(f);
  return v;
}

ContinuationStepper::Outcome ContinuationStepper::emit(BranchPoint point, std::optional<StopReason> stop_reason) {
  ++points_;
  return Outcome{std::move(point), stop_reason};
}

ContinuationStepper::Outcome ContinuationStepper::step() {
  const int m = s_.m;
  VectorXd direction_vec = t_;
  if (options_.predictor == Predictor::secant && x_before_.size() == m + 1) {
    direction_vec = x_ - x_before_;
    direction_vec.normalize();
  }
  const VectorXd prediction = x_ + ds_ * direction_vec;
  VectorXd y = prediction;
  int iterations = 0;
  const int chords_before = s_.chord_iterations;
  const bool converged = s_.correct(y, x_, direction_vec, ds_, options_.corrector == Corrector::hypersphere, options_, iterations);
  // The sign of the bordered determinant at the last point: test_values stores it as the BP
  // test function, values[1].
  const int det_sign = static_cast<int>(previous_.values[1]);
  Tangent tan_new;
  // On a piecewise smooth branch a corrector fails where the branch turns by more than 90
  // degrees at a corner: step onto the corner and leave it along the next piece instead.
  const bool onto_corner = !converged && corners_ && step_to_corner(s_, x_, direction_vec, det_sign, ds_, options_, y, tan_new, iterations);
  // Counted now: locating a special point below runs chord iterations of its own.
  const int chords = s_.chord_iterations - chords_before;

  // Reject a corrector that did not converge, went back along the branch, jumped away from
  // the prediction or turned too sharply; at the smallest step a corner is real (a
  // nonsmooth law kinks the branch): go through it.
  const bool smallest_step = ds_ <= 2 * options_.step_min;
  bool accepted = onto_corner || (converged && (y - x_).dot(t_) > 0 && (smallest_step || (y - prediction).norm() <= ds_));
  bool through_corner = false;
  double turn = 0;
  if (accepted && !onto_corner) {
    // Through a corner (smallest step) the branch goes on the way the step went: oriented by
    // the old tangent, a turn sharper than 90 degrees would send it back along itself.
    tan_new = s_.tangent(smallest_step ? VectorXd((y - x_).normalized()) : t_);
    turn = std::acos(std::clamp(t_.dot(tan_new.t), -1.0, 1.0));
    accepted = smallest_step || turn <= options_.max_angle;
    // A smooth branch turns in proportion to the step; a corner of a sampled C0 law (or a fold
    // narrower than a time sample) turns as much at half the step. Once seen, go through it
    // at this step instead of halving down to step_min and growing back over dozens of points.
    if (!accepted && corners_) {
      if (corner_.turn > 0 && ds_ <= 0.5 * corner_.step && turn >= 0.75 * corner_.turn) {
        tan_new = s_.tangent(VectorXd((y - x_).normalized()));
        accepted = through_corner = true;
      } else {
        corner_ = {ds_, turn, 0};
      }
    }
    // Along a branch the sign of det [R_u R_lambda; t^T] changes only at a branch point. Where
    // a piecewise smooth branch folds back close to itself, a long step can land on the part
    // coming back, the turn looking small: that point's tangent, oriented along the old one,
    // then has the other sign. Shorter steps follow the branch round; at the smallest step a
    // change of sign is a branch point.
    if (accepted && corners_ && !smallest_step && tan_new.det_sign != det_sign) accepted = through_corner = false;
  }
  if (!accepted) {
    if (!converged) ++summary_.failed_steps;
    ++summary_.step_halvings;
    ds_ *= 0.5;
    cut_ = true;
    if (ds_ < options_.step_min)
      return {std::nullopt, converged ? StopReason::step_size_underflow_on_curvature : StopReason::step_size_underflow};
    return {};
  }
  if (through_corner || onto_corner) ++summary_.corners_stepped_over;

  const double arc = (y - x_).norm();
  BranchPoint point{s_.unknowns(y), s_.parameter(y), tan_new.t, iterations, arc};
  const TestValues current = test_values(point, tan_new);
  record_special_points(y, point, current);
  const TestValues before = std::move(previous_);
  previous_ = current;
  x_before_ = x_;
  x_ = y;
  t_ = tan_new.t;
  const double lambda = point.lambda;
  // Crossing a bound of the window: land exactly on it, interpolating the last step.
  const bool beyond_end = (lambda - lambda_end_) * direction_ >= 0;
  const bool beyond_back = (lambda - lambda_back_) * direction_ < 0;
  if (beyond_end || beyond_back) {
    const double bound = beyond_end ? lambda_end_ : lambda_back_;
    const StopReason reason = beyond_end ? StopReason::reached_end : StopReason::left_range;
    const double lambda_before = s_.parameter(x_before_);
    const double f = (bound - lambda_before) / (lambda - lambda_before);
    VectorXd u_end = s_.unknowns(x_before_ + f * (x_ - x_before_));
    const int it = newton_at_fixed_parameter(s_.problem, u_end, bound, options_.tolerance, options_.max_iterations);
    if (it < 0) return emit(point, reason);
    summary_.newton_iterations += it;
    return emit({u_end, bound, t_, it, arc * f}, reason);
  }
  if (BranchPoint closing; window_.stop_when_closed && closes_on_first_point(y, closing)) return emit(closing, StopReason::closed);
  Outcome out = emit(point);

  s_.rescale(s_.unknowns(x_), {&x_, &x_before_}, t_);
  // A chord step counts half: it gains about half the digits of a Newton step near the
  // solution (linear against quadratic convergence) at a fraction of the cost. A corner's turn
  // says nothing of the curvature ahead: it does not size the next step.
  const bool at_corner = through_corner || onto_corner || smallest_step;
  AcceptedStep taken{ds_, iterations - 0.5 * chords, at_corner ? 0.0 : turn, {}, {}};
  for (size_t k = 0; k < types_.size(); ++k) {
    if (k == 1) continue;  // BP: the bordered determinant's magnitude is no distance to a zero
    taken.before.push_back(before.values[k]);
    taken.after.push_back(current.values[k]);
  }
  // A step that had to be cut is where the corrector's reach ends: growing straight back
  // would fail again (a non-smooth law's branch: a failed corrector costs max_iterations).
  const double factor = cut_ ? std::min(step_factor(taken, options_), 1.0) : step_factor(taken, options_);
  cut_ = false;
  // Past a corner the branch is as smooth as before it: back to the step that met it.
  ds_ = std::min(through_corner ? std::max(ds_ * factor, corner_.step) : ds_ * factor, options_.step_max);
  // A remembered turn only stands for the corner just ahead.
  if (through_corner || ++corner_.points_since > 4) corner_ = {};
  return out;
}

// Brackets the special points between the last point (x_, t_, previous_) and the new one y.
void ContinuationStepper::record_special_points(const VectorXd& y, const BranchPoint& point, const TestValues& current) {
  const int m = s_.m;
  const int index_new = points_;
  for (size_t k = 0; k < types_.size(); ++k) {
    const double f0 = previous_.values[k];
    const double f1 = k == 1 ? current.values[1] * std::exp(std::min(current.bp_log_det - previous_.bp_log_det, 600.0)) : current.values[k];
    if (!(f0 * f1 < 0)) continue;
    SpecialPoint sp{types_[k], index_new, false, point.lambda, point.u, point.tangent, ""};
    VectorXd located;
    Tangent located_tan;
    if (options_.locate && locator_.locate(k, x_, t_, f0, y, f1, previous_.bp_log_det, located, located_tan)) {
      const double along = t_.dot(located - x_) / std::max(t_.dot(y - x_), 1e-300);
      sp = {types_[k], along < 0.5 ? index_new - 1 : index_new, true, s_.parameter(located), s_.unknowns(located), located_tan.t, ""};
    } else if (types_[k] == "LP") {
      // Unlocated: the point where lambda is extreme.
      const bool was_rising = t_(m) > 0;
      if (was_rising ? s_.parameter(x_) > s_.parameter(y) : s_.parameter(x_) < s_.parameter(y))
        sp = {types_[k], index_new - 1, false, s_.parameter(x_), s_.unknowns(x_), t_, ""};
    }
    if (k >= 2) {
      sp.type = monitor_->classify(types_[k], BranchPoint{sp.u, sp.lambda, sp.tangent, 0, 0}, sp.located, sp.decided_by);
      // Two test functions may flip for one crossing (a nearly real pair): record it once.
      const auto same = [&](const SpecialPoint& q) { return q.type == sp.type && q.index == sp.index; };
      if (sp.type.empty() || std::any_of(special_points_.begin(), special_points_.end(), same)) continue;
    }
    special_points_.push_back(sp);
  }
}

// Back at the first point (an isolated branch, a closed tracking curve): the step's chord passes
// within a quarter step of it after the branch went more than two steps away from it (a loop
// only three steps across, as the tracked fold of a law narrower than a sample draws, went round
// 290 times under the former four). A closed curve ends on a copy of its first point. Called
// after the step: x_before_ is where it started, x_ = y where it ended.
bool ContinuationStepper::closes_on_first_point(const VectorXd& y, BranchPoint& closing) {
  const int m = s_.m;
  const VectorXd first_x = s_.pack(first_point_.u, first_point_.lambda);
  const VectorXd chord = y - x_before_;
  const double length = chord.norm();
  farthest_ = std::max(farthest_, (y - first_x).norm());
  const double along = length > 0 ? (first_x - x_before_).dot(chord) / length : -1.0;
  const double off = (first_x - x_before_ - along * chord / std::max(length, 1e-300)).norm();
  // A loop arrives with the orientation it left with; a branch that turned back on itself (a
  // sharp corner taken at the smallest step) passes the start going the other way.
  const VectorXd first_t = s_.pack(first_point_.u + first_point_.tangent.head(m).cwiseProduct(first_scale_),
                                   first_point_.lambda + first_point_.tangent(m) * first_parameter_scale_) -
                           first_x;
  const bool same_orientation = first_t.dot(t_) > 0;
  if (!(farthest_ > 2 * length && along >= 0 && along <= length && off <= 0.25 * length && same_orientation)) return false;
  closing = first_point_;
  closing.step = (first_x - x_before_).norm();
  return true;
}

}  // namespace hbtrack::continuation_detail
