#include "hbtrack/continuation/continuation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "hbtrack/util/dense_lu.hpp"
#include "hbtrack/util/phase_timer.hpp"

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

double inf_norm(const VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

// Tangent of the branch and the determinant of the bordered Jacobian used to compute it.
struct Tangent {
  VectorXd t;
  double log_det = 0;  // log |det [J R_lambda; b^T]| (scaled coordinates)
  int det_sign = 1;
};

// Scaled-coordinate view of the problem: X = [u ./ su; lambda / sl].
struct Scaled {
  ContinuationProblem& problem;
  VectorXd su;
  double sl;
  double rtol;
  int m;
  VectorXd r, r_lambda;
  MatrixXd jac;
  int jacobian_evaluations = 0;
  int newton_iterations = 0;
  int factorizations = 0;
  // Workspaces kept across iterations and points: a Newton iteration allocates no m x m matrix.
  MatrixXd newton_matrix{};   // the bordered matrix last factored by the corrector
  MatrixXd tangent_matrix{};  // the bordered matrix at the converged point
  DenseLU lu{};               // factors of newton_matrix, or of tangent_matrix after a fresh tangent
  VectorXd solution{}, refinement_residual{}, product{};
  VectorXd y_before{};  // where the corrector's last step started
  int residual_evaluations = 0;
  int chord_iterations = 0;  // all chord steps so far
  // lu holds the factors of the last Newton iteration of the corrector that just converged:
  // the tangent may start from them. Only within one corrector, so that a run resumed from a
  // saved state (which carries no factors) repeats the original exactly.
  bool newton_factors_current = false;

  // Re-scales scaled vectors after the unknown scale changed to that of the point u.
  void rescale(const VectorXd& u, std::initializer_list<VectorXd*> points, VectorXd& tangent_vec) {
    const VectorXd new_su = problem.unknown_scale(u);
    if (new_su == su) return;
    for (VectorXd* p : points)
      if (p->size() == m + 1) p->head(m) = p->head(m).cwiseProduct(su).cwiseQuotient(new_su);
    tangent_vec.head(m) = tangent_vec.head(m).cwiseProduct(su).cwiseQuotient(new_su);
    tangent_vec.normalize();
    su = new_su;
  }
  VectorXd pack(const VectorXd& u, double lambda) const {
    VectorXd x(m + 1);
    x.head(m) = u.cwiseQuotient(su);
    x(m) = lambda / sl;
    return x;
  }
  VectorXd unknowns(const VectorXd& x) const { return x.head(m).cwiseProduct(su); }
  double parameter(const VectorXd& x) const { return x(m) * sl; }
  // Evaluates R, dR/dX (scaled) at x; returns the relative residual.
  double evaluate(const VectorXd& x) {
    problem.evaluate(unknowns(x), parameter(x), r, &jac, &r_lambda);
    ++jacobian_evaluations;
    return inf_norm(r) / rtol;
  }
  // The bordered matrix a = [J diag(su), r_lambda sl; row], written into a kept workspace.
  void bordered(const VectorXd& row, MatrixXd& a) const {
    a.resize(m + 1, m + 1);
    a.topLeftCorner(m, m) = jac * su.asDiagonal();
    a.topRightCorner(m, 1) = r_lambda * sl;
    a.row(m) = row.transpose();
  }
  // Unit tangent at the last evaluated point, oriented along `reference` (also the border).
  // After a converged corrector whose Newton matrix had the same border, it is refined from
  // that matrix's factors instead of factoring anew (tangent_from_newton_factors).
  Tangent tangent(const VectorXd& reference) {
    bordered(reference, tangent_matrix);
    Tangent out;
    const bool same_border = newton_factors_current && newton_matrix.row(m).transpose() == reference;
    newton_factors_current = false;
    if (!(same_border && tangent_from_newton_factors(out))) {
      const ScopedPhase timing(Phase::factorization);
      lu.compute(tangent_matrix);
      ++factorizations;
      solution.setZero(m + 1);
      solution(m) = 1.0;
      lu.solve_in_place(solution);
      out.t = solution;
    }
    out.log_det = lu.log_abs_determinant();
    out.det_sign = lu.determinant_sign();
    out.t.normalize();
    if (out.t.dot(reference) < 0) out.t = -out.t;
    return out;
  }
  // The Newton matrix A of the corrector's last iteration differs from the tangent's matrix B
  // (same border) by the last step dy: iterative refinement of B t = e with A's factors gives
  // B's solution to working accuracy in a few O(m^2) steps, against an O(m^3) factorization.
  // A's determinant stands for B's (the BP test function): det B = det A det(I + A^-1 (B - A)),
  // and the second factor is positive when ||A^-1 (B - A)|| < 1, which also makes the
  // refinement converge; the bound 0.1 leaves room for the estimate of that norm, a lower
  // bound. False (the caller factors B) when the bound or the refinement fails, e.g. after a
  // long last Newton step or near a singular Jacobian.
  bool tangent_from_newton_factors(Tangent& out) {
    const ScopedPhase timing(Phase::factorization);
    newton_matrix = tangent_matrix - newton_matrix;  // B - A: A itself lives on in its factors
    const MatrixXd& change = newton_matrix;
    const double relative_change = estimate_norm1(
        m + 1,
        [&](VectorXd& v) {
          product.noalias() = change * v;
          v = product;
          lu.solve_in_place(v);
        },
        [&](VectorXd& v) {
          lu.solve_transposed_in_place(v);
          product.noalias() = change.transpose() * v;
          v = product;
        });
    if (!(relative_change <= 0.1)) return false;
    if (!refine_last_unit_solution(lu, tangent_matrix, solution, refinement_residual)) return false;
    out.t = solution;
    return true;
  }

  // Evaluates R alone at x (a chord iteration); returns the relative residual.
  double evaluate_residual(const VectorXd& x) {
    problem.evaluate(unknowns(x), parameter(x), r, nullptr, nullptr);
    ++residual_evaluations;
    return inf_norm(r) / rtol;
  }
  // Factors the Newton matrix [J; row] at the last evaluated point.
  void factor_newton_matrix(const VectorXd& row) {
    bordered(row, newton_matrix);
    const ScopedPhase timing(Phase::factorization);
    lu.compute(newton_matrix);
    ++factorizations;
  }

  // Newton on [R(y); P(y)] = 0 from y, with P the pseudo-arclength plane direction.(y - x) = ds
  // or the hypersphere |y - x|^2 = ds^2. On success the Jacobian at y is the last evaluated.
  // With options.reuse_factorization, an iteration after the first keeps the factors of the
  // last Newton matrix (a chord step: one residual and an O(m^2) solve instead of a Jacobian
  // and an O(m^3) factorization) as long as each step shrinks the error by options.contraction;
  // after a step that does not, the corrector goes on as Newton, from where that step started
  // when it made the error worse.
  bool correct(VectorXd& y, const VectorXd& x, const VectorXd& direction, double ds, bool hypersphere,
               const ContinuationOptions& options, int& iterations) {
    newton_factors_current = false;
    const double plane_tolerance = 1e-8 * ds * std::max(1.0, ds);
    double last_error = std::numeric_limits<double>::infinity();
    for (int it = 0; it <= options.max_iterations; ++it) {
      const bool chord = options.reuse_factorization && newton_factors_current;
      const double residual = chord ? evaluate_residual(y) : evaluate(y);
      const VectorXd d = y - x;
      double p;
      VectorXd p_row;
      if (hypersphere) {
        p = d.squaredNorm() - ds * ds;
        p_row = 2.0 * d;
        if (p_row.norm() == 0.0) p_row = direction;
      } else {
        p = direction.dot(d) - ds;
        p_row = direction;
      }
      // The error in units of the tolerances: converged at <= 1.
      const double error = std::max(residual / options.tolerance, std::abs(p) / plane_tolerance);
      if (std::isfinite(residual) && error <= 1.0) {
        if (chord) evaluate(y);  // the tangent needs the Jacobian at y
        iterations = it;
        return true;
      }
      if (chord && !(error <= options.contraction * last_error)) {
        // The kept factors no longer contract: Newton from here, or from where the step
        // started when it made things worse.
        if (!(error < last_error)) y = y_before;
        return finish_with_newton(y, x, direction, ds, hypersphere, options, iterations, it);
      }
      if (!std::isfinite(residual)) return false;
      if (it == options.max_iterations) return false;
      if (!chord) factor_newton_matrix(p_row);
      solution.resize(m + 1);
      solution.head(m) = -r;
      solution(m) = -p;
      {
        const ScopedPhase timing(Phase::factorization);
        lu.solve_in_place(solution);
      }
      newton_factors_current = true;
      if (!solution.allFinite()) return false;
      if (chord) ++chord_iterations;
      y_before = y;
      last_error = error;
      y += solution;
      ++newton_iterations;
    }
    return false;
  }
  // The rest of a corrector as plain Newton from y, after `done` iterations.
  bool finish_with_newton(VectorXd& y, const VectorXd& x, const VectorXd& direction, double ds, bool hypersphere,
                          const ContinuationOptions& options, int& iterations, int done) {
    ContinuationOptions newton = options;
    newton.reuse_factorization = false;
    newton.max_iterations = options.max_iterations - done;
    int more = 0;
    const bool converged = correct(y, x, direction, ds, hypersphere, newton, more);
    iterations = done + more;
    return converged;
  }
};

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

namespace {
// Newton at fixed lambda; `used` counts the iterations spent, also when it fails.
int newton_counting(ContinuationProblem& problem, VectorXd& u, double lambda, double tolerance, int max_iterations, int& used) {
  VectorXd r, r_lambda;
  MatrixXd jac;
  DenseLU lu;
  const double scale = problem.residual_scale();
  used = 0;
  for (int it = 0; it <= max_iterations; ++it) {
    problem.evaluate(u, lambda, r, &jac, &r_lambda);
    if (!r.allFinite()) return -1;
    if (inf_norm(r) <= tolerance * scale) return it;
    if (it == max_iterations) break;
    const ScopedPhase timing(Phase::factorization);
    lu.compute(jac);
    r = -r;
    lu.solve_in_place(r);
    ++used;
    if (!r.allFinite()) return -1;
    u += r;
  }
  return -1;
}
}  // namespace

int newton_at_fixed_parameter(ContinuationProblem& problem, VectorXd& u, double lambda, double tolerance,
                              int max_iterations) {
  int used = 0;
  return newton_counting(problem, u, lambda, tolerance, max_iterations, used);
}

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
    const int first_iterations = newton_counting(problem, u, lambda_start, options.tolerance, 3 * options.max_iterations, used);
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

    // Reject a corrector that did not converge, went back along the branch, jumped away from
    // the prediction or turned too sharply; at the smallest step a corner is real (a
    // nonsmooth law kinks the branch): go through it.
    const bool smallest_step = ds <= 2 * options.step_min;
    bool accepted = converged && (y - x).dot(t) > 0 && (smallest_step || (y - prediction).norm() <= ds);
    Tangent tan_new;
    bool through_corner = false;
    if (accepted) {
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
          ++summary.corners_stepped_over;
        } else {
          corner = {ds, turn, 0};
        }
      }
    }
    if (!accepted) {
      if (!converged) ++summary.failed_steps;
      ++summary.step_halvings;
      ds *= 0.5;
      if (ds < options.step_min) return finish(converged ? "step_size_underflow_on_curvature" : "step_size_underflow");
      continue;
    }

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
