#pragma once
// The continuation engine's view of a problem in scaled coordinates X = [u ./ su; lambda / sl]:
// evaluation, the unit tangent (and the bordered determinant, the BP test function) and the
// corrector (pseudo-arclength or hypersphere Newton, with chord iterations). Private to
// src/continuation.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/util/dense_lu.hpp"
#include "hbtrack/util/single_precision_lu.hpp"
#include "hbtrack/util/phase_timer.hpp"

namespace hbtrack::continuation_detail {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// The Newton matrix's size from which the chord corrector factors it in single precision:
// below, its O(m^3) factorization is a small part of an iteration (the AFT is most of it on the
// one- and two-dof examples), so double keeps their iterations as they were.
constexpr int kSinglePrecisionFrom = 128;

inline double inf_norm(const VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

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
  // The chord corrector's Newton matrix in single precision (newton_single): its steps are
  // approximate anyway, and the residual that decides convergence is evaluated in double.
  SinglePrecisionLU newton_lu_single{};
  bool newton_single = false;
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
    // Single-precision factors would give the determinant's sign of the rounded matrix.
    const bool same_border = newton_factors_current && !newton_single && newton_matrix.row(m).transpose() == reference;
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
  void factor_newton_matrix(const VectorXd& row, bool single) {
    bordered(row, newton_matrix);
    const ScopedPhase timing(Phase::factorization);
    if (single)
      newton_lu_single.compute(newton_matrix);
    else
      lu.compute(newton_matrix);
    newton_single = single;
    ++factorizations;
  }
  // step <- N^-1 step with the Newton matrix's factors; single-precision factors whose
  // solve is not finite are replaced by double ones.
  void solve_newton(VectorXd& step) {
    const ScopedPhase timing(Phase::factorization);
    if (newton_single && newton_lu_single.solve_in_place(step)) return;
    if (newton_single) {
      lu.compute(newton_matrix);
      newton_single = false;
      ++factorizations;
    }
    lu.solve_in_place(step);
  }

  // Newton on [R(y); P(y)] = 0 from y, with P the pseudo-arclength plane direction.(y - x) = ds
  // or the hypersphere |y - x|^2 = ds^2. On success the Jacobian at y is the last evaluated.
  // With options.reuse_factorization, an iteration after the first keeps the factors of the
  // last Newton matrix (a chord step: one residual and an O(m^2) solve instead of a Jacobian
  // and an O(m^3) factorization) as long as each step shrinks the error by options.contraction;
  // after a step that does not, the corrector goes on as Newton, from where that step started
  // when it made the error worse. From kSinglePrecisionFrom unknowns, on a problem that allows
  // it (single_precision_chords), the chord corrector factors in single precision; the Newton
  // that takes over after a failed contraction factors in double.
  bool correct(VectorXd& y, const VectorXd& x, const VectorXd& direction, double ds, bool hypersphere, const ContinuationOptions& options,
               int& iterations) {
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
      if (!chord)
        factor_newton_matrix(p_row, options.reuse_factorization && m + 1 >= kSinglePrecisionFrom && problem.single_precision_chords());
      solution.resize(m + 1);
      solution.head(m) = -r;
      solution(m) = -p;
      solve_newton(solution);
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

}  // namespace hbtrack::continuation_detail
