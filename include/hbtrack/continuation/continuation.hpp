#pragma once
// Arc-length continuation of the solutions of R(u, lambda) = 0, independent of what R is
// (paper section 2.2; the design of BifurcationKit's problem object / LOCA's group).
// Steps are measured in scaled coordinates (u / unknown_scale, lambda / parameter_scale) so
// that the parameter and the unknowns weigh alike.
#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hbtrack/util/choices.hpp"
#include "hbtrack/util/special_point_type.hpp"
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack {

class ContinuationProblem {
 public:
  virtual ~ContinuationProblem() = default;
  virtual int size() const = 0;  // number of unknowns u (lambda comes on top)
  // r = R(u, lambda); when jacobian is given also J = dR/du and r_lambda = dR/dlambda.
  virtual void evaluate(const Eigen::VectorXd& u, double lambda, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian,
                        Eigen::VectorXd* r_lambda) = 0;
  // Scale of the unknowns near the point u: re-read after every accepted point, so a problem
  // may let it follow the solution (small responses then keep their resolution).
  virtual Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const = 0;
  virtual double parameter_scale() const = 0;
  // Convergence: ||R||_inf <= tolerance * residual_scale().
  virtual double residual_scale() const = 0;
  // True when R is only piecewise smooth in u (a C0 law sampled in time): its branch has corners,
  // which the engine recognises (a turn that does not shrink with the step) and steps over.
  virtual bool has_corners() const { return false; }
  // True when the chord corrector may factor the Newton matrix in single precision (from 128
  // unknowns): where the matrix is well enough conditioned that single precision's rounding
  // barely slows the chord steps (NFRCs without stability: 16-20 % less time on the blade and
  // rotor 67), not on the fold systems of `track`, whose chords then failed more than they saved.
  virtual bool single_precision_chords() const { return false; }
};

struct ContinuationOptions {
  double step = 0.02;      // initial arc-length step (scaled units)
  double step_min = 1e-7;  // a failed step is halved until it falls below this
  // A safety bound only: the step is sized by the branch (target_angle, target_iterations,
  // the special points ahead). Scaled units: 1 is the whole parameter range.
  double step_max = 0.5;
  int max_points = 5000;
  int max_iterations = 15;    // Newton iterations per corrector
  int target_iterations = 4;  // the step grows when Newton needs fewer, shrinks when more
  // The turn of the tangent per step (radians) the step is sized for: the step grows where the
  // branch is straighter, shrinks where it turns more (below max_angle, which rejects a step).
  double target_angle = 0.15;
  // Chord iterations: the corrector keeps its Newton matrix's factors while each step shrinks
  // the error at least by `contraction` (then factors anew); false: a fresh Jacobian and
  // factorization at every iteration.
  bool reuse_factorization = true;
  double contraction = 0.25;
  double tolerance = 1e-9;  // on ||R||_inf / residual_scale
  // A step whose tangent turns by more than this (radians), or whose corrector moves farther
  // than the step from the prediction, is retried at half length: it cut a corner or jumped
  // to another part of the branch.
  double max_angle = 0.3;
  Predictor predictor = Predictor::tangent;
  Corrector corrector = Corrector::pseudo_arclength;
  double wall_time_limit = 0;  // seconds, 0 for none; stops with "time_limit" (as --time-limit does)
  // Refine each bracketed special point onto the zero of its test function (secant along the
  // branch); false leaves it at the bracketing point.
  bool locate = true;
  void validate() const;  // throws std::invalid_argument naming the field and the rule
};

struct BranchPoint {
  Eigen::VectorXd u;
  double lambda = 0;
  Eigen::VectorXd tangent;  // unit tangent in scaled coordinates, size+1 entries, lambda last
  int newton_iterations = 0;
  double step = 0;  // arc length from the previous point (scaled)
  // False when a monitor that may skip points (BranchMonitor::may_skip_points) did not evaluate
  // this point: its verdict is that of the evaluated points around it, which agree.
  bool monitored = true;
};

struct SpecialPoint {
  SpecialPointType type = SpecialPointType::limit_point;
  int index = 0;         // the branch point nearest to it
  bool located = false;  // true when refined onto the zero of its test function
  double lambda = 0;
  Eigen::VectorXd u;
  Eigen::VectorXd tangent;  // scaled, as BranchPoint::tangent
  std::string decided_by;   // PD/NS: the stability method that classified it ("hill", "monodromy")
};

struct ContinuationSummary {
  StopReason stop_reason = StopReason::running;  // reached_end, left_range, closed, max_points, step_size_underflow, ...
  int points = 0;
  int newton_iterations = 0;
  int failed_steps = 0;
  int step_halvings = 0;
  int jacobian_evaluations = 0;
  // Dense LUs of the bordered system: one per Newton step, plus one per tangent that could not
  // be refined from the last Newton step's factors.
  int factorizations = 0;
  int chord_iterations = 0;      // of newton_iterations, those with kept factors
  int residual_evaluations = 0;  // without the Jacobian (one per chord iteration and corrector)
  int corners_stepped_over = 0;  // steps taken through a corner (ContinuationProblem::has_corners)
  double wall_s = 0;
};

struct ContinuationResult {
  std::vector<BranchPoint> points;
  std::vector<SpecialPoint> special_points;
  ContinuationSummary summary;
  bool success() const;  // ended at the end of the range, or as asked (max_points)
};

// Called for each accepted point (index from 0); return false to stop ("interrupted").
using PointObserver = std::function<bool(const BranchPoint&, int)>;

// Test functions beyond the engine's own (LP: the lambda component of the tangent; BP: the
// determinant of the bordered Jacobian [R_u R_lambda; t^T]). A sign change between consecutive
// points brackets a special point of that type, then located like the built-in ones.
class BranchMonitor {
 public:
  virtual ~BranchMonitor() = default;
  virtual std::vector<SpecialPointType> types() const = 0;  // e.g. {period_doubling, neimark_sacker}
  // Called at every accepted point (before the observer) and at trial points while locating.
  virtual std::vector<double> test_functions(const BranchPoint& p) = 0;
  // Whether a sign change of one of these test functions is a real special point: called at
  // the located point (located = true) or, when location failed, at the bracketing point.
  virtual bool confirm(SpecialPointType /*type*/, const BranchPoint& /*p*/, bool /*located*/) { return true; }
  // What a sign change of test function `type` is, read at the point (a PD test may flip
  // because a multiplier pair crossed elsewhere): the type to record, nullopt to drop it.
  // `decided_by` names what decided. Default: confirm() keeps the type.
  virtual std::optional<SpecialPointType> classify(SpecialPointType type, const BranchPoint& p, bool located, std::string& /*decided_by*/) {
    if (confirm(type, p, located)) return type;
    return std::nullopt;
  }
  // True when the monitor is costly and may be evaluated at some points only: where its test
  // functions, extrapolated from the last two evaluations, could change sign, where the engine's
  // fold test is about to, and at least every kMaxSkippedPoints + 1 points. The points between
  // two evaluated ones are passed to the observer only once both are known (monitored = false);
  // when the two disagree (a test function's sign or the verdict), every point between them is
  // evaluated and the change located as usual.
  virtual bool may_skip_points() const { return false; }
  // What the monitor concludes at p, as a number that changes wherever the conclusion does
  // (FloquetMonitor: the number of multipliers outside the unit circle).
  virtual int verdict(const BranchPoint& /*p*/) { return 0; }
};

// A lazy monitor (may_skip_points) is evaluated at least once every kMaxSkippedPoints + 1 points.
inline constexpr int kMaxSkippedPoints = 4;

// Solve R(u, lambda) = 0 at fixed lambda by Newton from u. Returns iterations used, -1 on failure.
int newton_at_fixed_parameter(ContinuationProblem& problem, Eigen::VectorXd& u, double lambda, double tolerance, int max_iterations);

// Follows the branch from an approximate solution u0 at lambda_start towards lambda_end.
// Stops with "reached_end" on lambda_end, "left_range" when the branch turns back below
// lambda_start (both landed on exactly).
ContinuationResult continue_branch(ContinuationProblem& problem, const Eigen::VectorXd& u0, double lambda_start, double lambda_end,
                                   const ContinuationOptions& options, const PointObserver& observer = {},
                                   BranchMonitor* monitor = nullptr);

// The parameter interval a branch may explore, and how to leave the start.
struct ParameterWindow {
  double lambda_min = 0, lambda_max = 0;
  int direction = 1;              // +1: leave the start with lambda increasing, -1: decreasing
  bool stop_when_closed = false;  // stop ("closed") when the branch returns to its first point
};

// Everything the engine's next step depends on, taken between two steps (after a point was
// accepted and the step size adapted, or after a rejected step was halved). Restarting from it
// continues the branch exactly as the run it was taken from would have: same points, bit for
// bit (`hbtrack frc --resume`).
struct ContinuationState {
  int points = 0;                   // points accepted so far; the next one gets this index
  Eigen::VectorXd x, x_before;      // last point and the one before it, scaled ([u ./ scale; lambda / sl])
  Eigen::VectorXd tangent;          // unit tangent at x, scaled
  Eigen::VectorXd unknown_scale;    // the scale x, x_before and tangent are expressed in
  double step = 0;                  // arc length of the next step
  bool step_cut = false;            // the step was halved since the last point: the next one does not grow
  double farthest = 0;              // farthest scaled distance from the first point (closure test)
  std::vector<double> test_values;  // special-point test functions at x (brackets the next step)
  double bp_log_det = 0;            // the BP test function's reference
  // A lazy monitor's history (x is always a point it evaluated): its test functions at the
  // evaluated point before x (empty: none), the arc length back to it, and x's verdict.
  std::vector<double> earlier_test_values;
  double earlier_distance = 0;
  int monitor_verdict = 0;
  BranchPoint first;  // the first point and its scaling (closure test)
  Eigen::VectorXd first_scale;
  double first_parameter_scale = 0;
  std::vector<SpecialPoint> special_points;  // found so far
  ContinuationSummary summary;               // counters so far
};

// Optional restart and checkpoint hooks of continue_within.
struct ContinuationRestart {
  const ContinuationState* resume_from = nullptr;  // continue from here instead of u0 (indices go on)
  // Called between steps, to save the state: after the first point, then when state_interval_s
  // seconds have passed since the last call, and once more when the run stops, whatever the
  // reason (so an interrupted run's state covers every point it accepted). A checkpoint is
  // written whole and fsynced: at every point that was 3 s of a 30 s blade NFRC.
  std::function<void(const ContinuationState&)> on_state;
  double state_interval_s = 1.0;  // 0: at every step
  // Without resume_from: leave the start along this direction (scaled coordinates of this
  // problem, size + 1 entries, e.g. the tangent of the same branch computed with other
  // unknowns and mapped onto these) instead of the window's direction; the window still says
  // which bound ends the branch. Goes on the way a branch already travelled, across a fold too.
  const Eigen::VectorXd* leave_along = nullptr;
};

// Follows the branch from u0 at lambda_start (inside the window) in the window's direction
// until it crosses the bound it headed for ("reached_end"), the other bound ("left_range"),
// or, when asked, closes on itself ("closed", last point = first point). With
// restart.resume_from, u0 is not used and result.points holds only the points after the state,
// while the summary and special points include those before it.
ContinuationResult continue_within(ContinuationProblem& problem, const Eigen::VectorXd& u0, double lambda_start,
                                   const ParameterWindow& window, const ContinuationOptions& options, const PointObserver& observer = {},
                                   BranchMonitor* monitor = nullptr, const ContinuationRestart& restart = {});

}  // namespace hbtrack
