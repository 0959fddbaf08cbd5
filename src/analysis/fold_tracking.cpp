#include "hbtrack/analysis/fold_tracking.hpp"

#include "hbtrack/analysis/critical_exponent_system.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

void FoldTrackingOptions::validate() const {
  if (!std::isfinite(parameter_min) || !std::isfinite(parameter_max) || !(parameter_min < parameter_max))
    throw std::invalid_argument("range: must be LO:HI with LO < HI, both finite");
  continuation.validate();
}

StopReason FoldTrackingResult::stop_reason() const {
  if (legs.empty()) return StopReason::not_started;
  bool capped = false;
  for (const ContinuationSummary& s : legs) {
    switch (s.stop_reason) {
      case StopReason::reached_end:
      case StopReason::left_range:
      case StopReason::closed:
      case StopReason::strong_resonance:
        break;
      case StopReason::max_points:
        capped = true;
        break;
      default:
        return s.stop_reason;
    }
  }
  return closed ? StopReason::closed : capped ? StopReason::max_points : StopReason::completed;
}

SpecialPointType special_point_type(TrackedPoint tracked) {
  switch (tracked) {
    case TrackedPoint::neimark_sacker:
      return SpecialPointType::neimark_sacker;
    case TrackedPoint::period_doubling:
      return SpecialPointType::period_doubling;
    case TrackedPoint::limit_point:
      break;
  }
  return SpecialPointType::limit_point;
}

TrackedPoint parse_tracked_point(const std::string& name, std::string_view field) {
  constexpr TrackedPoint trackable[] = {TrackedPoint::limit_point, TrackedPoint::neimark_sacker, TrackedPoint::period_doubling};
  std::string names[std::size(trackable)];
  for (size_t i = 0; i < std::size(trackable); ++i) {
    names[i] = to_string(special_point_type(trackable[i]));
    if (names[i] == name) return trackable[i];
  }
  const std::string_view views[] = {names[0], names[1], names[2]};
  throw_unknown_choice(field, views, name);
}

bool FoldTrackingResult::success() const {
  const StopReason reason = stop_reason();
  return reason == StopReason::closed || reason == StopReason::max_points || reason == StopReason::completed;
}

namespace {

std::unique_ptr<FoldSystem> make_fold_system(const FoldTrackingOptions& o, const HarmonicBalance& hbm, int parameter,
                                             const FoldScales& scales) {
  if (o.tracked == TrackedPoint::neimark_sacker)
    return std::make_unique<CriticalExponentSystem>(hbm, parameter, scales, CriticalExponent::neimark_sacker);
  if (o.tracked == TrackedPoint::period_doubling)
    return std::make_unique<CriticalExponentSystem>(hbm, parameter, scales, CriticalExponent::period_doubling);
  if (o.method == TrackingMethod::extended) return std::make_unique<ExtendedFoldSystem>(hbm, parameter, scales);
  return std::make_unique<BorderedFoldSystem>(hbm, parameter, scales);
}

std::string size_misfit(const std::string& field, Eigen::Index size, Eigen::Index expected, const std::string& why) {
  if (size == expected) return "";
  return field + " holds " + std::to_string(size) + " values, expected " + std::to_string(expected) + " (" + why + ")";
}

// Ends an NS curve where its frequency reaches 0 (R1, 1:1 resonance: the pair of multipliers meets
// at +1, where the NS curve ends on a fold curve) or w/2 (R2, 1:2: at -1, on a PD curve): beyond,
// nu changes sign and the system retraces the same points (P(-i nu) is P(i nu) conjugated). The
// engine locates the zero of the test function; the observer then ends the leg there.
class ResonanceMonitor final : public BranchMonitor {
 public:
  explicit ResonanceMonitor(const CriticalExponentSystem& system) : system_(system) {}
  std::vector<SpecialPointType> types() const override { return {SpecialPointType::resonance_1_1, SpecialPointType::resonance_1_2}; }
  std::vector<double> test_functions(const BranchPoint& p) override { return system_.resonance_tests(p.u); }
  std::optional<SpecialPointType> classify(SpecialPointType type, const BranchPoint&, bool, std::string& decided_by) override {
    decided_by = "hill";
    ended = true;
    return type;
  }
  bool ended = false;

 private:
  const CriticalExponentSystem& system_;
};

// A located extremum of lambda near point `index` of a leg: a minimum when lambda was falling
// along the leg just before it. The bracket is the pair of neighbours whose tangents' lambda
// components (`slopes`, one per leg point) differ in sign (the engine reports the nearer of the
// two as `index`).
CurveExtremumType extremum_type(const std::vector<double>& slopes, int index) {
  auto rising = [&](int k) { return slopes[static_cast<size_t>(k)] > 0; };
  const int last = static_cast<int>(slopes.size()) - 1;
  int before = index;
  if (index + 1 > last || rising(index) == rising(index + 1)) before = std::max(index - 1, 0);
  return rising(before) ? CurveExtremumType::parameter_max : CurveExtremumType::parameter_min;
}

}  // namespace

LocatedFold locate_fold(const HarmonicBalance& hbm, int parameter, const VectorXd& x, double omega, const FoldScales& scales,
                        const ContinuationOptions& options, const FoldScales& fallback) {
  // First to the case's own tolerance (`fallback`), then a few iterations toward the stricter
  // `scales`: round-off on a stiff model may deny those extra digits, and then the fold located
  // to the case tolerance stands.
  const double value = hbm.parameters().value(parameter);
  BorderedFoldSystem plain(hbm, parameter, fallback);
  VectorXd u = plain.start_at(x, omega, value);
  LocatedFold f;
  f.converged = newton_at_fixed_parameter(plain, u, value, options.tolerance, 3 * options.max_iterations) >= 0;
  f.x = plain.harmonics(u);
  f.omega = plain.omega(u);
  if (f.converged && scales.force < fallback.force) {
    BorderedFoldSystem system(hbm, parameter, scales);
    VectorXd strict = system.start_at(f.x, f.omega, value);
    if (newton_at_fixed_parameter(system, strict, value, options.tolerance, 4) >= 0) {
      f.x = system.harmonics(strict);
      f.omega = system.omega(strict);
    }
  }
  return f;
}

std::string tracking_state_misfit(const FoldTrackingState& state, const FoldTrackingOptions& options, int harmonic_unknowns) {
  const int q = harmonic_unknowns;
  const TrackingMethod method = options.method;
  // The continuation's unknowns (FoldSystem::size: x, omega and, extended, the null vector; an
  // NS or PD curve: x, nu and omega), then its parameter.
  const bool extended = method == TrackingMethod::extended, exponent = options.tracked != TrackedPoint::limit_point;
  const Eigen::Index size = (exponent ? q + 2 : extended ? 2 * q + 1 : q + 1) + 1;
  const std::string why = "this case's " + std::to_string(q) + " unknowns, " +
                          (exponent ? "the critical exponent's frequency, omega and the parameter of an NS or PD tracking"
                                    : std::string(extended ? "their null vector, " : "") + "omega and the parameter of " +
                                          (extended ? "an extended" : "a bordered") + " tracking");
  std::string misfit = size_misfit("state.x", state.continuation.x.size(), size, why);
  // An NS or PD system's borders (on Hill's pencil) are checked as it restores them.
  if (misfit.empty() && method == TrackingMethod::bordered && !exponent) {
    const size_t given = state.borders.size();
    if (given != 2) return "tracking.borders holds " + std::to_string(given) + " vectors, expected 2 (a bordered tracking's borders)";
    for (size_t i = 0; i < given && misfit.empty(); ++i)
      misfit = size_misfit("tracking.borders[" + std::to_string(i) + "]", state.borders[i].size(), q, "this case's unknowns");
  }
  for (size_t i = 0; i < state.extrema.size() && misfit.empty(); ++i)
    misfit = size_misfit("tracking.extrema[" + std::to_string(i) + "].x", state.extrema[i].x.size(), q, "this case's unknowns");
  return misfit;
}

FoldTrackingResult track_fold(const HarmonicBalance& hbm, int parameter, const VectorXd& x, double omega, const FoldScales& scales,
                              const FoldTrackingOptions& options, const std::vector<OutputDof>& outputs, const FoldObserver& observer,
                              const FoldTrackingRestart& restart) {
  options.validate();
  const double gamma0 = hbm.parameters().value(parameter);
  if (!(options.parameter_min <= gamma0 && gamma0 <= options.parameter_max))
    throw std::invalid_argument("range: must contain the parameter's value at the limit point, " + std::to_string(gamma0));
  std::unique_ptr<FoldSystem> system = make_fold_system(options, hbm, parameter, scales);
  // The outputs of each point, at its own parameter value (the recovery of condensed dofs
  // depends on it): an evaluator of our own, the caller's stays as it is.
  HarmonicBalance at_point(hbm);
  FoldTrackingResult result;
  const FoldTrackingState* resumed = restart.resume_from;
  if (resumed) {
    if (resumed->leg < 1 || resumed->leg > 2) throw std::invalid_argument("tracking state: leg must be 1 or 2");
    const std::string misfit = tracking_state_misfit(*resumed, options, hbm.unknowns());
    if (!misfit.empty()) throw std::invalid_argument("tracking state: " + misfit);
    result.legs = resumed->finished_legs;
    result.extrema = resumed->extrema;
    for (FoldExtremum& e : result.extrema) {  // their outputs, as the finished legs recorded them
      at_point.set_parameter(parameter, e.parameter);
      e.recorded = record_point(at_point, e.x, e.omega, outputs);
    }
    result.points_before = resumed->curve_points;
  }
  for (int leg = resumed ? resumed->leg : 1; leg <= 2; ++leg) {
    const bool resuming = resumed && leg == resumed->leg;
    VectorXd u0;
    if (resuming)
      system->restore_borders(resumed->borders);
    else
      u0 = system->start_at(x, omega, gamma0);
    const ParameterWindow window{options.parameter_min, options.parameter_max, leg == 1 ? -1 : 1, leg == 1};
    const int offset = resuming ? resumed->leg_offset : result.curve_points() - (leg == 2 ? 1 : 0);
    std::vector<double> slopes = resuming ? resumed->lambda_slopes : std::vector<double>{};
    ContinuationRestart leg_restart;
    if (resuming) leg_restart.resume_from = &resumed->continuation;
    if (restart.on_state)
      leg_restart.on_state = [&](const ContinuationState& state) {
        restart.on_state(
            FoldTrackingState{leg, offset, result.curve_points(), state, system->borders(), slopes, result.legs, result.extrema});
      };
    bool stopped = false;
    const auto* critical = dynamic_cast<const CriticalExponentSystem*>(system.get());
    std::unique_ptr<ResonanceMonitor> resonance;
    if (critical && critical->kind() == CriticalExponent::neimark_sacker) resonance = std::make_unique<ResonanceMonitor>(*critical);
    const auto add_point = [&](const VectorXd& u, double lambda) {
      FoldCurvePoint point{system->harmonics(u), system->omega(u), lambda, leg, {}, system->critical_frequency(u)};
      at_point.set_parameter(parameter, lambda);
      point.recorded = record_point(at_point, point.x, point.omega, outputs);
      result.points.push_back(std::move(point));
      stopped = observer && !observer(result.points.back(), result.curve_points() - 1);
      return !stopped;
    };
    ContinuationResult c = continue_within(
        *system, u0, gamma0, window, options.continuation,
        [&](const BranchPoint& p, int index) {
          system->accepted(p.u, p.lambda);
          slopes.push_back(p.tangent(p.tangent.size() - 1));
          if (leg == 2 && index == 0) return true;          // the start, already the first point of leg 1
          if (resonance && resonance->ended) return false;  // past the resonance: the leg ends on it
          return add_point(p.u, p.lambda);
        },
        resonance.get(), leg_restart);
    const auto extremum_at = [&](const SpecialPoint& sp, CurveExtremumType type, int index) {
      FoldExtremum e;
      e.type = type;
      e.located = sp.located;
      e.x = system->harmonics(sp.u);
      e.omega = system->omega(sp.u);
      e.parameter = sp.lambda;
      e.critical_frequency = system->critical_frequency(sp.u);
      e.index = index;
      at_point.set_parameter(parameter, sp.lambda);
      e.recorded = record_point(at_point, e.x, e.omega, outputs);
      return e;
    };
    // The located resonance is the leg's last point (its bracket's far end is not kept).
    const SpecialPoint* end = nullptr;
    for (const SpecialPoint& sp : c.special_points)
      if (!end && resonance && resonance->ended &&
          (sp.type == SpecialPointType::resonance_1_1 || sp.type == SpecialPointType::resonance_1_2))
        end = &sp;
    if (end) {
      c.summary.stop_reason = StopReason::strong_resonance;
      if (!stopped) add_point(end->u, end->lambda);
    }
    // gamma is extreme at a resonance too (beyond it the curve retraces itself), and the engine
    // locates that extremum within the step that brackets the resonance: not an extremum of the
    // curve, the resonance stands for it.
    const auto at_end = [&](const SpecialPoint& sp) { return end && sp.index >= end->index - 1; };
    result.legs.push_back(c.summary);
    for (const SpecialPoint& sp : c.special_points) {
      if (sp.type != SpecialPointType::limit_point || at_end(sp)) continue;  // the extrema of gamma; the engine's BP is not a fold event
      result.extrema.push_back(extremum_at(sp, extremum_type(slopes, sp.index),
                                           leg == 2 && sp.index == 0 ? 0 : std::max(0, offset + sp.index)));  // leg 2 starts at point 0
    }
    if (end)
      result.extrema.push_back(extremum_at(
          *end, end->type == SpecialPointType::resonance_1_1 ? CurveExtremumType::resonance_1_1 : CurveExtremumType::resonance_1_2,
          result.curve_points() - 1));
    if (c.summary.stop_reason == StopReason::closed) {
      result.closed = true;
      break;
    }
    if (stopped || c.summary.stop_reason == StopReason::no_convergence_at_start) break;
  }
  return result;
}

std::vector<IsolaCandidate> compute_isolas(const HarmonicBalance& caller, int parameter, double value,
                                           const std::vector<std::vector<FoldCurvePoint>>& curves, const FoldScales& scales,
                                           const NfrcOptions& options, const std::vector<OutputDof>& outputs, bool follow_branches,
                                           const RecordedObserver& observer) {
  HarmonicBalance hbm = caller.with_parameter(parameter, value);
  // Two more digits than the branch needs, so that its continuation starts without a Newton
  // step at the limit point (where R_x is singular).
  FoldScales strict = scales;
  strict.force *= 1e-2;
  const ParameterWindow window{std::min(options.omega_start, options.omega_end), std::max(options.omega_start, options.omega_end), 1, true};
  auto same_fold = [&](const VectorXd& xa, double wa, const VectorXd& xb, double wb) {
    const double size = std::max({xa.cwiseAbs().maxCoeff(), xb.cwiseAbs().maxCoeff(), scales.length});
    return std::abs(wa - wb) <= 1e-6 * std::abs(wb) && (xa - xb).cwiseAbs().maxCoeff() <= 1e-4 * size;
  };
  std::vector<IsolaCandidate> out;
  for (const auto& curve : curves) {
    for (size_t i = 0; i + 1 < curve.size(); ++i) {
      const FoldCurvePoint &a = curve[i], &b = curve[i + 1];
      // A crossing of gamma = value inside the segment, or at its end (counted once), or at the
      // first point of a curve (the tracked limit point itself, when value is its parameter's).
      // The first point counts even when the next one has the same value: a curve started at its
      // range's end has a first leg of two points, both at the end (the rotor 67 study's
      // validation at mu = 1e-4 found no crossing on the curve started from its own limit point).
      const bool at_first_point = i == 0 && a.parameter == value;
      if (a.leg != b.leg || (a.parameter == b.parameter && !at_first_point)) continue;
      if (!((a.parameter - value) * (b.parameter - value) < 0 || b.parameter == value || at_first_point)) continue;
      const double f = at_first_point ? 0.0 : (value - a.parameter) / (b.parameter - a.parameter);
      IsolaCandidate cand;
      cand.start =
          locate_fold(hbm, parameter, a.x + f * (b.x - a.x), a.omega + f * (b.omega - a.omega), strict, options.continuation, scales);
      if (!cand.start.converged) {
        cand.status = "failed";
        out.push_back(std::move(cand));
        continue;
      }
      for (size_t k = 0; k < out.size() && cand.same_as < 0; ++k) {
        const IsolaCandidate& other = out[k];
        if (other.status == "duplicate" || other.status == "failed") continue;
        if (same_fold(cand.start.x, cand.start.omega, other.start.x, other.start.omega)) cand.same_as = static_cast<int>(k);
        for (const SpecialPoint& sp : other.branch.continuation.special_points)
          if (sp.type == SpecialPointType::limit_point && sp.located && same_fold(cand.start.x, cand.start.omega, sp.u, sp.lambda))
            cand.same_as = static_cast<int>(k);
      }
      if (cand.same_as >= 0) {
        cand.status = "duplicate";
      } else if (cand.start.omega < window.lambda_min || cand.start.omega > window.lambda_max) {
        cand.status = "outside_range";  // a limit point beyond the case's frequency range
      } else if (!follow_branches) {
        cand.status = "located";
      } else {
        cand.branch = compute_branch(hbm, options, outputs, cand.start.x, cand.start.omega, window, observer);
        const StopReason reason = cand.branch.continuation.summary.stop_reason;
        const bool open = reason == StopReason::reached_end || reason == StopReason::left_range;
        cand.status = reason == StopReason::closed ? "isola" : open ? "open" : "failed";
      }
      out.push_back(std::move(cand));
    }
  }
  return out;
}

}  // namespace hbtrack
