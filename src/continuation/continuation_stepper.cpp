#include "continuation_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "corner_step.hpp"
#include "fixed_parameter_newton.hpp"
#include "step_control.hpp"

namespace hbtrack::continuation_detail {

namespace {
// The unit tangent's lambda component below which a start lies on a fold (a regular start's is orders
// of magnitude larger; a located fold's is rounding, 1e-13 and less).
constexpr double kStartsOnAFold = 1e-8;
}  // namespace

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
  if (monitor) {
    for (const auto& t : monitor->types()) types_.push_back(t);
    lazy_ = monitor->may_skip_points();
  }
}

bool ContinuationStepper::start(const VectorXd& u0, double lambda_start, BranchPoint& first, const VectorXd* leave_along) {
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
  if (leave_along && leave_along->size() != s_.m + 1)
    throw std::invalid_argument("continuation: the direction to leave the start along has " + std::to_string(leave_along->size()) +
                                " entries, the problem " + std::to_string(s_.m + 1));
  VectorXd lambda_axis = VectorXd::Zero(s_.m + 1);
  lambda_axis(s_.m) = direction_;
  // Along a given direction the tangent's border is that direction itself (nearly the tangent,
  // so the bordered matrix is well conditioned even on a fold) and the orientation follows it.
  Tangent tan = s_.tangent(leave_along ? VectorXd(leave_along->normalized()) : lambda_axis);
  // Started on a fold (an isola from its limit point), the tangent's lambda component is zero to
  // rounding (1e-13 to 1e-16 on the tutorial's isola), so its sign, which the window's direction
  // would pick, changed with the BLAS kernel: the isola ran either way round on two CPUs. There
  // the branch leaves towards the larger response (|u| growing), a sign the whole state sets.
  if (leave_along) {
    // s_.tangent oriented it along the given direction.
  } else if (std::abs(tan.t(s_.m)) < kStartsOnAFold) {
    if (x_.head(s_.m).dot(tan.t.head(s_.m)) < 0) tan.t = -tan.t;
  } else if (tan.t(s_.m) * direction_ < 0) {
    tan.t = -tan.t;
  }
  t_ = tan.t;
  first_point_ = BranchPoint{u, lambda_start, t_, iterations, 0.0};
  MonitoredPoint start_point{first_point_, x_, t_, s_.su, engine_test_values(tan), 0.0, 0, 0};
  if (monitor_) evaluate_monitor(start_point);
  previous_ = start_point.values;
  history_.last = previous_.values;
  last_monitored_ = std::move(start_point);
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
  // A state is taken where the monitor evaluated its point (settled()): the history goes on
  // from there, arc lengths counted from it.
  history_ = MonitorHistory{previous_.values, state.earlier_test_values, 0.0, -state.earlier_distance, 0};
  last_monitored_ = MonitoredPoint{
      BranchPoint{s_.unknowns(x_), s_.parameter(x_), t_, 0, 0.0}, x_, t_, s_.su, previous_, 0.0, points_ - 1, state.monitor_verdict};
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
  ContinuationState state;
  state.points = points_;
  state.x = x_;
  state.x_before = x_before_;
  state.tangent = t_;
  state.unknown_scale = s_.su;
  state.step = ds_;
  state.step_cut = cut_;
  state.farthest = farthest_;
  state.test_values = previous_.values;
  state.bp_log_det = previous_.bp_log_det;
  if (lazy_) {
    state.earlier_test_values = history_.before;
    state.earlier_distance = history_.last_arc - history_.before_arc;
    state.monitor_verdict = last_monitored_.verdict;
  }
  state.first = first_point_;
  state.first_scale = first_scale_;
  state.first_parameter_scale = first_parameter_scale_;
  state.special_points = special_points_;
  state.summary = summary();
  return state;
}

TestValues ContinuationStepper::engine_test_values(const Tangent& tan) const {
  TestValues v;
  v.bp_log_det = tan.log_det;
  v.values = {tan.t(s_.m), static_cast<double>(tan.det_sign)};
  return v;
}

void ContinuationStepper::evaluate_monitor(MonitoredPoint& p) {
  p.values.values.resize(2);
  for (double f : monitor_->test_functions(p.point)) p.values.values.push_back(f);
  p.verdict = lazy_ ? monitor_->verdict(p.point) : 0;
  p.point.monitored = true;
}

VectorXd ContinuationStepper::in_current_scale(const VectorXd& v, const VectorXd& su_then, bool normalize) const {
  if (su_then == s_.su) return v;
  VectorXd out = v;
  out.head(s_.m) = v.head(s_.m).cwiseProduct(su_then).cwiseQuotient(s_.su);
  if (normalize) out.normalize();
  return out;
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
    if (ds_ < options_.step_min) return {{}, converged ? StopReason::step_size_underflow_on_curvature : StopReason::step_size_underflow};
    return {};
  }
  if (through_corner || onto_corner) ++summary_.corners_stepped_over;

  const double arc = (y - x_).norm();
  BranchPoint point{s_.unknowns(y), s_.parameter(y), tan_new.t, iterations, arc};
  const double lambda = point.lambda;
  // Crossing a bound of the window ends the branch exactly on it; so does closing on itself.
  const bool beyond_end = (lambda - lambda_end_) * direction_ >= 0;
  const bool beyond_back = (lambda - lambda_back_) * direction_ < 0;
  BranchPoint closing;
  const bool closes = !beyond_end && !beyond_back && window_.stop_when_closed && closes_on_first_point(x_, y, tan_new.t, closing);
  arc_ += arc;
  MonitoredPoint now{point, y, tan_new.t, s_.su, engine_test_values(tan_new), arc_, points_, 0};
  // A lazy monitor waits where its verdict cannot change; the branch's last point settles it.
  if (monitor_ &&
      (!lazy_ || beyond_end || beyond_back || closes || monitor_due(history_, arc_, previous_.values, now.values.values, arc, turn)))
    evaluate_monitor(now);
  else if (monitor_)
    now.point.monitored = false;
  const TestValues current = now.values;
  record_engine_special_points(y, point, current);
  std::vector<BranchPoint> settled_points;
  if (now.evaluated()) {
    settled_points = settle_with(now);
  } else {
    pending_.push_back(now);
    ++history_.points_since;
    history_.turn_since += turn;
  }
  ++points_;
  const TestValues before = std::move(previous_);
  previous_ = current;
  x_before_ = x_;
  x_ = y;
  t_ = tan_new.t;
  if (beyond_end || beyond_back) {
    // Land on the bound, interpolating the last step: that point replaces the step's.
    const double bound = beyond_end ? lambda_end_ : lambda_back_;
    const StopReason reason = beyond_end ? StopReason::reached_end : StopReason::left_range;
    const double lambda_before = s_.parameter(x_before_);
    const double f = (bound - lambda_before) / (lambda - lambda_before);
    VectorXd u_end = s_.unknowns(x_before_ + f * (x_ - x_before_));
    const int it = newton_at_fixed_parameter(s_.problem, u_end, bound, options_.tolerance, options_.max_iterations);
    if (it >= 0) {
      summary_.newton_iterations += it;
      settled_points.back() = BranchPoint{u_end, bound, t_, it, arc * f};
    }
    return {std::move(settled_points), reason};
  }
  if (closes) {
    settled_points.back() = closing;
    return {std::move(settled_points), StopReason::closed};
  }

  s_.rescale(s_.unknowns(x_), {&x_, &x_before_}, t_);
  if (now.evaluated()) {
    // Kept in the scale a saved state has, so a resumed run brackets from the same numbers.
    last_monitored_.x = x_;
    last_monitored_.t = t_;
    last_monitored_.su = s_.su;
  }
  // A chord step counts half: it gains about half the digits of a Newton step near the
  // solution (linear against quadratic convergence) at a fraction of the cost. A corner's turn
  // says nothing of the curvature ahead: it does not size the next step.
  const bool at_corner = through_corner || onto_corner || smallest_step;
  AcceptedStep taken{ds_, iterations - 0.5 * chords, at_corner ? 0.0 : turn, {}, {}};
  for (size_t k = 0; k < types_.size(); ++k) {
    if (k == 1) continue;  // BP: the bordered determinant's magnitude is no distance to a zero
    if (k >= before.values.size() || k >= current.values.size()) continue;  // a point the monitor skipped
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
  return {std::move(settled_points), std::nullopt};
}

std::vector<BranchPoint> ContinuationStepper::settle() {
  if (pending_.empty()) return {};
  MonitoredPoint last = std::move(pending_.back());
  pending_.pop_back();
  evaluate_monitor(last);
  previous_ = last.values;  // the newest point is x_: its state now carries the monitor's values
  std::vector<BranchPoint> out = settle_with(std::move(last));
  last_monitored_.x = x_;
  last_monitored_.t = t_;
  last_monitored_.su = s_.su;
  return out;
}

std::vector<BranchPoint> ContinuationStepper::settle_with(MonitoredPoint now) {
  const auto signs_differ = [](const TestValues& a, const TestValues& b) {
    for (size_t k = 2; k < a.values.size() && k < b.values.size(); ++k)
      if (!(a.values[k] * b.values[k] > 0)) return true;
    return false;
  };
  if (!pending_.empty() && (now.verdict != last_monitored_.verdict || signs_differ(last_monitored_.values, now.values)))
    for (MonitoredPoint& p : pending_) evaluate_monitor(p);
  pending_.push_back(std::move(now));
  const size_t found_before = special_points_.size();
  std::vector<BranchPoint> out;
  for (MonitoredPoint& p : pending_) {
    out.push_back(p.point);
    if (!p.evaluated()) continue;
    record_monitor_special_points(last_monitored_, p);
    history_.before = std::move(history_.last);
    history_.before_arc = history_.last_arc;
    history_.last = p.values.values;
    history_.last_arc = p.arc;
    last_monitored_ = std::move(p);
  }
  history_.points_since = 0;
  history_.turn_since = 0;
  pending_.clear();
  // Found out of order when pending points were evaluated late: kept in branch order.
  if (special_points_.size() > found_before)
    std::stable_sort(special_points_.begin(), special_points_.end(),
                     [](const SpecialPoint& a, const SpecialPoint& b) { return a.index < b.index; });
  return out;
}

// Brackets the engine's special points (LP, BP) between the last point (x_, t_, previous_) and
// the new one y.
void ContinuationStepper::record_engine_special_points(const VectorXd& y, const BranchPoint& point, const TestValues& current) {
  const int m = s_.m;
  const int index_new = points_;
  for (size_t k = 0; k < 2; ++k) {
    const double f0 = previous_.values[k];
    const double f1 = k == 1 ? current.values[1] * std::exp(std::min(current.bp_log_det - previous_.bp_log_det, 600.0)) : current.values[k];
    if (!(f0 * f1 < 0)) continue;
    SpecialPoint sp{types_[k], index_new, false, point.lambda, point.u, point.tangent, ""};
    VectorXd located;
    Tangent located_tan;
    if (options_.locate && locator_.locate(k, x_, t_, f0, y, f1, previous_.bp_log_det, located, located_tan)) {
      const double along = t_.dot(located - x_) / std::max(t_.dot(y - x_), 1e-300);
      sp = {types_[k], along < 0.5 ? index_new - 1 : index_new, true, s_.parameter(located), s_.unknowns(located), located_tan.t, ""};
    } else if (types_[k] == SpecialPointType::limit_point) {
      // Unlocated: the point where lambda is extreme.
      const bool was_rising = t_(m) > 0;
      if (was_rising ? s_.parameter(x_) > s_.parameter(y) : s_.parameter(x_) < s_.parameter(y))
        sp = {types_[k], index_new - 1, false, s_.parameter(x_), s_.unknowns(x_), t_, ""};
    }
    special_points_.push_back(sp);
  }
}

void ContinuationStepper::record_monitor_special_points(const MonitoredPoint& a, const MonitoredPoint& b) {
  const VectorXd xa = in_current_scale(a.x, a.su, false), ta = in_current_scale(a.t, a.su, true);
  const VectorXd xb = in_current_scale(b.x, b.su, false);
  for (size_t k = 2; k < types_.size() && k < a.values.values.size() && k < b.values.values.size(); ++k) {
    const double f0 = a.values.values[k], f1 = b.values.values[k];
    if (!(f0 * f1 < 0)) continue;
    SpecialPoint sp{types_[k], b.index, false, b.point.lambda, b.point.u, b.point.tangent, ""};
    VectorXd located;
    Tangent located_tan;
    if (options_.locate && locator_.locate(k, xa, ta, f0, xb, f1, 0.0, located, located_tan)) {
      const double along = ta.dot(located - xa) / std::max(ta.dot(xb - xa), 1e-300);
      sp = {types_[k], along < 0.5 ? a.index : b.index, true, s_.parameter(located), s_.unknowns(located), located_tan.t, ""};
    }
    const std::optional<SpecialPointType> type =
        monitor_->classify(types_[k], BranchPoint{sp.u, sp.lambda, sp.tangent, 0, 0}, sp.located, sp.decided_by);
    if (!type) continue;
    sp.type = *type;
    // Two test functions may flip for one crossing (a nearly real pair): record it once.
    const auto same = [&](const SpecialPoint& q) { return q.type == sp.type && q.index == sp.index; };
    if (std::any_of(special_points_.begin(), special_points_.end(), same)) continue;
    special_points_.push_back(sp);
  }
}

// Back at the first point (an isolated branch, a closed tracking curve): the step's chord passes
// within a quarter step of it after the branch went more than two steps away from it (a loop
// only three steps across, as the tracked fold of a law narrower than a sample draws, went round
// 290 times under the former four). A closed curve ends on a copy of its first point. Called
// with the step from `start` to y and the tangent t at y.
bool ContinuationStepper::closes_on_first_point(const VectorXd& start, const VectorXd& y, const VectorXd& t, BranchPoint& closing) {
  const int m = s_.m;
  const VectorXd first_x = s_.pack(first_point_.u, first_point_.lambda);
  const VectorXd chord = y - start;
  const double length = chord.norm();
  farthest_ = std::max(farthest_, (y - first_x).norm());
  const double along = length > 0 ? (first_x - start).dot(chord) / length : -1.0;
  const double off = (first_x - start - along * chord / std::max(length, 1e-300)).norm();
  // A loop arrives with the orientation it left with; a branch that turned back on itself (a
  // sharp corner taken at the smallest step) passes the start going the other way.
  const VectorXd first_t = s_.pack(first_point_.u + first_point_.tangent.head(m).cwiseProduct(first_scale_),
                                   first_point_.lambda + first_point_.tangent(m) * first_parameter_scale_) -
                           first_x;
  const bool same_orientation = first_t.dot(t) > 0;
  if (!(farthest_ > 2 * length && along >= 0 && along <= length && off <= 0.25 * length && same_orientation)) return false;
  closing = first_point_;
  closing.step = (first_x - start).norm();
  return true;
}

}  // namespace hbtrack::continuation_detail
