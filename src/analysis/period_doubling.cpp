#include "hbtrack/analysis/period_doubling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hbtrack {

HarmonicBalanceOptions period_doubled_options(const HarmonicBalanceOptions& o) {
  if (o.subharmonic != 1)
    throw std::invalid_argument("period doubling: the system is already subharmonic (nu = " + std::to_string(o.subharmonic) + ")");
  std::vector<int> list;
  const std::vector<int> period_one = o.selected_harmonics();
  for (int k = 0; k <= 2 * o.harmonics; ++k) {
    const bool even_listed = k % 2 == 0 && std::find(period_one.begin(), period_one.end(), k / 2) != period_one.end();
    if (even_listed || k % 2 == 1) list.push_back(k);
  }
  HarmonicBalanceOptions doubled = o;
  doubled.select(list);
  doubled.subharmonic = 2;
  doubled.samples = 2 * o.effective_samples();
  return doubled;
}

Eigen::VectorXd embed_in_subharmonic_basis(const FourierBasis& from, const FourierBasis& to, int nu, int dofs, const Eigen::VectorXd& x) {
  const Eigen::VectorXd dense = from.to_dense(x, dofs);
  Eigen::VectorXd wide = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs) * (2 * to.harmonics() + 1));
  for (int k : from.harmonic_numbers()) {
    if (nu * k > to.harmonics())
      throw std::invalid_argument("embed_in_subharmonic_basis: harmonic " + std::to_string(k) + " is beyond the target basis");
    if (k == 0) {
      wide.head(dofs) = dense.head(dofs);
    } else {
      wide.segment((2 * nu * k - 1) * dofs, dofs) = dense.segment((2 * k - 1) * dofs, dofs);
      wide.segment(2 * nu * k * dofs, dofs) = dense.segment(2 * k * dofs, dofs);
    }
  }
  const Eigen::VectorXd out = to.from_dense(wide, dofs);
  if (std::abs(to.to_dense(out, dofs).squaredNorm() - dense.squaredNorm()) > 1e-12 * (1 + dense.squaredNorm()))
    throw std::invalid_argument("embed_in_subharmonic_basis: the target basis does not list every harmonic of the source");
  return out;
}

namespace {

// The odd harmonics of omega / 2 (the motion's part of period 2T) of u, the rest zero.
Eigen::VectorXd odd_harmonics_of(const FourierBasis& b, int q, const Eigen::VectorXd& u) {
  Eigen::VectorXd odd = Eigen::VectorXd::Zero(u.size());
  for (int c = 0; c < b.coefficients(); ++c)
    if (b.harmonic_of(c) % 2 == 1) odd.segment(c * q, q) = u.segment(c * q, q);
  return odd;
}

// Where a leg rejoins the period-T branch, located rather than sampled: the last step crosses
// the branch point and lands wherever the corrector converges (on the period-T branch or the
// same branch shifted by T). At that branch point the doubled branch is parametrised regularly
// by its odd amplitude a (omega - omega_bp grows as a^2 on a smooth law, as |a| at worst), so
// Newton on R(u, omega) = 0, <e, odd(u)> = a, e the odd part's direction at the last point
// before the rejoin, follows it as a falls by 4x per stage to a_end = 1e-3 of the leg's largest:
// omega is then within 1e-3 of the bubble's width of the branch point (1e-6 on a smooth law).
// That branch point is the harmonic balance's own PD in the doubled basis, a truncation of its
// own (docs/stability.md). A last point already below a_end is the end. False when Newton fails.
bool locate_rejoin(HarmonicBalance& doubled, const BranchPoint& last, double largest_odd, int max_iterations, SpecialPoint& end) {
  const int n = doubled.unknowns(), q = doubled.retained_dofs();
  const FourierBasis& b = doubled.basis();
  const Eigen::VectorXd odd = odd_harmonics_of(b, q, last.u);
  const double a_end = 1e-3 * largest_odd;
  end.type = SpecialPointType::period_doubling;
  end.located = true;
  end.u = last.u;
  end.lambda = last.lambda;
  if (!(odd.norm() > a_end)) return true;  // the last step already ended there
  const Eigen::VectorXd e = odd / odd.norm();
  Eigen::VectorXd z(n + 1);
  z.head(n) = last.u;
  z(n) = last.lambda;
  Eigen::VectorXd r, r_omega, f(n + 1);
  Eigen::MatrixXd jac, bordered = Eigen::MatrixXd::Zero(n + 1, n + 1);
  bordered.row(n).head(n) = e.transpose();  // <e, u> reads only the odd harmonics: e is zero elsewhere
  for (double a = odd.norm() / 4;; a = std::max(a / 4, a_end)) {
    bool converged = false;
    for (int it = 0; it < max_iterations && !converged; ++it) {
      doubled.evaluate(z.head(n), z(n), r, &jac, &r_omega);
      f.head(n) = r;
      f(n) = e.dot(z.head(n)) - a;
      bordered.topLeftCorner(n, n) = jac;
      bordered.topRightCorner(n, 1) = r_omega;
      const Eigen::VectorXd dz = bordered.partialPivLu().solve(f);
      if (!dz.allFinite()) return false;
      z -= dz;
      // Round-off of the state: the update has stopped moving it.
      converged = dz.lpNorm<Eigen::Infinity>() <= 1e-10 * z.head(n).lpNorm<Eigen::Infinity>();
    }
    if (!converged) return false;
    if (a == a_end) break;
  }
  end.u = z.head(n);
  end.lambda = z(n);
  return true;
}

}  // namespace

SwitchedBranch switch_at_period_doubling(HarmonicBalance& doubled, const FourierBasis& basis, const NfrcOptions& options,
                                         const std::vector<OutputDof>& outputs, const Eigen::VectorXd& x_pd, double omega_pd,
                                         const Eigen::VectorXd& known, const RecordedObserver& leg_observer) {
  const int q = doubled.retained_dofs(), n = static_cast<int>(x_pd.size());
  if (doubled.subharmonic() != 2) throw std::invalid_argument("switch_at_period_doubling: the system must balance harmonics of omega / 2");
  if (known.size() != n + 1) throw std::invalid_argument("switch_at_period_doubling: the known direction has the wrong size");
  const Eigen::VectorXd x = embed_in_subharmonic_basis(basis, doubled.basis(), 2, q, x_pd);
  Eigen::VectorXd direction(doubled.unknowns() + 1);
  direction.head(doubled.unknowns()) = embed_in_subharmonic_basis(basis, doubled.basis(), 2, q, known.head(n));
  direction(doubled.unknowns()) = known(n);
  // The odd harmonics (the motion's part of period 2T) along the leg, against the first point's.
  Eigen::VectorXd first_odd;
  struct LegEnd {
    bool rejoined = false;
    double largest_odd = 0;
    BranchPoint last_on_branch;  // the last point before the rejoin
  };
  std::vector<LegEnd> legs;  // in the order computed: away, through
  const RecordedObserver stop_at_rejoin = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    const Eigen::VectorXd odd = odd_harmonics_of(doubled.basis(), q, p.u);
    if (index == 0) {
      first_odd = odd;
      legs.emplace_back();
    }
    LegEnd& leg = legs.back();
    leg.largest_odd = std::max(leg.largest_odd, odd.norm());
    leg.rejoined = index > 0 && (odd.norm() <= 1e-6 * leg.largest_odd || odd.dot(first_odd) < 0);
    if (leg.rejoined) return false;
    leg.last_on_branch = p;
    return !leg_observer || leg_observer(p, rec, index);
  };
  SwitchedBranch s = switch_at_branch_point(doubled, options, outputs, x, omega_pd, direction, true, true, stop_at_rejoin);
  // Each rejoined leg: the point that crossed is dropped (it lies on the period-T branch or on
  // the same branch shifted by T, not on this one), and its end, the PD where its odd harmonics
  // vanish, is located as a special point.
  NfrcResult* results[] = {&s.away, &s.through};
  for (size_t k = 0; k < legs.size() && k < 2; ++k) {
    if (!legs[k].rejoined) continue;
    ContinuationResult& leg = results[k]->continuation;
    leg.summary.stop_reason = StopReason::rejoined;
    leg.points.pop_back();
    results[k]->recorded.pop_back();
    leg.summary.points = static_cast<int>(leg.points.size());
    const int last = static_cast<int>(leg.points.size()) - 1;
    for (SpecialPoint& p : leg.special_points) p.index = std::min(p.index, last);  // one found on the dropped step
    SpecialPoint end;
    end.index = last;
    if (locate_rejoin(doubled, legs[k].last_on_branch, legs[k].largest_odd, 4 * options.continuation.max_iterations, end))
      leg.special_points.push_back(end);
  }
  return s;
}

}  // namespace hbtrack
