#pragma once
// Limit-point tracking: the curve of the NFRC's limit points as a second parameter gamma
// changes, followed both ways from a limit point, and the isolated branches it reveals
// (paper sections 3 and 5.2; method notes sections 6 and 7).
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_systems.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/util/choices.hpp"
#include "hbtrack/util/special_point_type.hpp"

namespace hbtrack {

// What a tracking run follows: a limit point (fold), or a Floquet exponent on the imaginary
// axis (critical_exponent_system.hpp): a Neimark-Sacker or a period-doubling point.
enum class TrackedPoint { limit_point, neimark_sacker, period_doubling };
// Its special-point type (named so in summary.json's options.tracking.point), and back from the
// name: another name throws std::invalid_argument "FIELD: must be LP, NS or PD, got 'x'".
SpecialPointType special_point_type(TrackedPoint tracked);
TrackedPoint parse_tracked_point(const std::string& name, std::string_view field);

struct FoldTrackingOptions {
  TrackedPoint tracked = TrackedPoint::limit_point;
  TrackingMethod method = TrackingMethod::bordered;  // of a limit point (NS and PD: bordered on Hill's pencil)
  double parameter_min = 0, parameter_max = 0;
  ContinuationOptions continuation;
  void validate() const;  // throws std::invalid_argument naming the field and the rule
};

struct FoldCurvePoint {
  Eigen::VectorXd x;
  double omega = 0;
  double parameter = 0;
  int leg = 1;  // 1: from the start towards parameter_min; 2: from the start towards parameter_max
  RecordedPoint recorded;
  // NS, PD: the crossing exponent's frequency |Im lambda| (the NS frequency); NaN for a fold.
  double critical_frequency = std::numeric_limits<double>::quiet_NaN();
};

// A local extremum of gamma along the curve, located: a minimum is where a pair of limit points
// is born (an isolated branch appears, or the main branch starts to fold), a maximum where a pair
// disappears (an isola merges with another branch, or a fold vanishes).
struct FoldExtremum {
  CurveExtremumType type = CurveExtremumType::parameter_min;
  bool located = false;
  Eigen::VectorXd x;
  double omega = 0, parameter = 0;
  int index = 0;  // the curve point (FoldTrackingResult::points) nearest to it
  RecordedPoint recorded;
  double critical_frequency = std::numeric_limits<double>::quiet_NaN();  // as FoldCurvePoint's
};

struct FoldTrackingResult {
  // Leg 1 from the start, then leg 2 from the start (not repeated). A resumed run holds only
  // the points after its checkpoint: the first has curve index points_before.
  std::vector<FoldCurvePoint> points;
  int points_before = 0;
  int curve_points() const { return points_before + static_cast<int>(points.size()); }
  std::vector<FoldExtremum> extrema;
  std::vector<ContinuationSummary> legs;
  bool closed = false;  // leg 1 came back to the start: the curve is a loop
  // The first leg's stop reason that is not an end as asked (a bound, closure, max_points), or
  // not_started without legs; else closed (a loop), max_points (a leg cut there: the curve is
  // incomplete) or completed.
  StopReason stop_reason() const;
  bool success() const;  // every leg ended as asked: closed, max_points or completed
};

using FoldObserver = std::function<bool(const FoldCurvePoint&, int index)>;

// A tracking run between two steps: enough to go on exactly as the uninterrupted run would.
struct FoldTrackingState {
  int leg = 1;                           // the leg under way
  int leg_offset = 0;                    // curve index of its point k is leg_offset + k (k >= 1)
  int curve_points = 0;                  // curve points accepted so far, all legs
  ContinuationState continuation;        // the leg's continuation engine
  std::vector<Eigen::VectorXd> borders;  // the fold system's (FoldSystem::borders)
  std::vector<double> lambda_slopes;     // the leg's tangents' parameter components, per point
  std::vector<ContinuationSummary> finished_legs;
  std::vector<FoldExtremum> extrema;  // of the finished legs (recorded outputs not kept)
};

// Why `state` cannot resume a tracking of `options` (method, point tracked) on a system of `harmonic_unknowns` unknowns,
// naming the checkpoint's field ("" when it can): a state saved for another model or method has
// vectors of other sizes, which the engine would combine with this system's (numbers or a crash).
std::string tracking_state_misfit(const FoldTrackingState& state, const FoldTrackingOptions& options, int harmonic_unknowns);

// Optional checkpoint hooks of track_fold, as ContinuationRestart for one branch.
struct FoldTrackingRestart {
  const FoldTrackingState* resume_from = nullptr;
  std::function<void(const FoldTrackingState&)> on_state;  // between two steps
};

// Follows the limit point near (x, omega) (an LP located on an NFRC at the parameter's current
// value) while parameter `parameter` of hbm moves within [parameter_min, parameter_max].
FoldTrackingResult track_fold(const HarmonicBalance& hbm, int parameter, const Eigen::VectorXd& x, double omega, const FoldScales& scales,
                              const FoldTrackingOptions& options, const std::vector<OutputDof>& outputs, const FoldObserver& observer = {},
                              const FoldTrackingRestart& restart = {});

// A limit point of the NFRC at the parameter's current value, from an approximation: Newton on
// the minimally augmented system in `scales`, or, when round-off keeps it from that tolerance, in
// the looser `fallback` scales.
struct LocatedFold {
  bool converged = false;
  Eigen::VectorXd x;
  double omega = 0;
};
LocatedFold locate_fold(const HarmonicBalance& hbm, int parameter, const Eigen::VectorXd& x, double omega, const FoldScales& scales,
                        const ContinuationOptions& options, const FoldScales& fallback);

// ---- isolated branches ---------------------------------------------------------------------

// The branch through one crossing of a tracking curve with gamma = value.
struct IsolaCandidate {
  LocatedFold start;
  std::string status;  // "isola" (closed on itself), "open" (reached the omega window: main
                       // branch), "duplicate" (a limit point of a branch already computed),
                       // "outside_range" (beyond the case's omega range), "located" (branches
                       // not followed), "failed"
  int same_as = -1;    // for duplicates: the candidate whose branch holds this limit point
  NfrcResult branch;   // for isola and open
};

// At parameter value `value`: every crossing of the tracking curves `curves` with it, refined
// onto the limit point, and the branch through each new one followed within the options' omega
// range until it closes. Stability as options.stability. With follow_branches false only the
// limit points are located (the cheap check that a validation NFRC's LPs lie on the curves).
// `observer` sees the points of every branch followed (index 0 starts a branch).
std::vector<IsolaCandidate> compute_isolas(const HarmonicBalance& hbm, int parameter, double value,
                                           const std::vector<std::vector<FoldCurvePoint>>& curves, const FoldScales& scales,
                                           const NfrcOptions& options, const std::vector<OutputDof>& outputs, bool follow_branches = true,
                                           const RecordedObserver& observer = {});

}  // namespace hbtrack
