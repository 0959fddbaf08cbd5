#pragma once
// Arc-length continuation of the solutions of R(u, lambda) = 0, independent of what R is
// (paper section 2.2; the design of BifurcationKit's problem object / LOCA's group).
// Steps are measured in scaled coordinates (u / unknown_scale, lambda / parameter_scale) so
// that the parameter and the unknowns weigh alike.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

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
};

struct ContinuationOptions {
  double step = 0.02;          // initial arc-length step (scaled units)
  double step_min = 1e-7;      // a failed step is halved until it falls below this
  double step_max = 0.1;
  int max_points = 5000;
  int max_iterations = 15;     // Newton iterations per corrector
  int target_iterations = 4;   // the step grows when Newton needs fewer, shrinks when more
  double tolerance = 1e-9;     // on ||R||_inf / residual_scale
  // A step whose tangent turns by more than this (radians), or whose corrector moves farther
  // than the step from the prediction, is retried at half length: it cut a corner or jumped
  // to another part of the branch.
  double max_angle = 0.3;
  std::string predictor = "tangent";           // tangent | secant (paper eq 12)
  std::string corrector = "pseudo_arclength";  // pseudo_arclength | hypersphere (paper eq 14)
  double wall_time_limit = 0;  // seconds, 0 for none
  void validate() const;       // throws std::invalid_argument naming the field and the rule
};

struct BranchPoint {
  Eigen::VectorXd u;
  double lambda = 0;
  Eigen::VectorXd tangent;  // unit tangent in scaled coordinates, size+1 entries, lambda last
  int newton_iterations = 0;
  double step = 0;          // arc length from the previous point (scaled)
};

struct SpecialPoint {
  std::string type;      // LP, BP, PD, NS, ...
  int index = 0;         // branch point index
  bool located = false;  // true when refined onto the exact singular point
  double lambda = 0;
  Eigen::VectorXd u;
};

struct ContinuationSummary {
  std::string stop_reason;  // reached_end, left_range, max_points, step_size_underflow, ...
  int points = 0;
  int newton_iterations = 0;
  int failed_steps = 0;
  int step_halvings = 0;
  int jacobian_evaluations = 0;
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

// Solve R(u, lambda) = 0 at fixed lambda by Newton from u. Returns iterations used, -1 on failure.
int newton_at_fixed_parameter(ContinuationProblem& problem, Eigen::VectorXd& u, double lambda, double tolerance,
                              int max_iterations);

// Follows the branch from an approximate solution u0 at lambda_start towards lambda_end.
ContinuationResult continue_branch(ContinuationProblem& problem, const Eigen::VectorXd& u0, double lambda_start,
                                   double lambda_end, const ContinuationOptions& options,
                                   const PointObserver& observer = {});

}  // namespace hbtrack
