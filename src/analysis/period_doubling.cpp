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
  const FourierBasis& b = doubled.basis();
  auto odd_part = [&](const Eigen::VectorXd& u) {
    Eigen::VectorXd odd = Eigen::VectorXd::Zero(u.size());
    for (int c = 0; c < b.coefficients(); ++c)
      if (b.harmonic_of(c) % 2 == 1) odd.segment(c * q, q) = u.segment(c * q, q);
    return odd;
  };
  Eigen::VectorXd first_odd;
  double largest = 0;
  std::vector<bool> rejoined;  // per leg, in the order computed: away, through
  const RecordedObserver stop_at_rejoin = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    const Eigen::VectorXd odd = odd_part(p.u);
    if (index == 0) {
      first_odd = odd;
      largest = 0;
      rejoined.push_back(false);
    }
    largest = std::max(largest, odd.norm());
    rejoined.back() = index > 0 && (odd.norm() <= 1e-6 * largest || odd.dot(first_odd) < 0);
    if (rejoined.back()) return false;
    return !leg_observer || leg_observer(p, rec, index);
  };
  SwitchedBranch s = switch_at_branch_point(doubled, options, outputs, x, omega_pd, direction, true, true, stop_at_rejoin);
  if (rejoined.size() > 0 && rejoined[0]) s.away.continuation.summary.stop_reason = StopReason::rejoined;
  if (rejoined.size() > 1 && rejoined[1]) s.through.continuation.summary.stop_reason = StopReason::rejoined;
  return s;
}

}  // namespace hbtrack
