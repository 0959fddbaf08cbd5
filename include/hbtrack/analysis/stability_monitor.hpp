#pragma once
// Stability of every branch point (Floquet exponents by Hill's method or the monodromy matrix)
// and the period-doubling / Neimark-Sacker test functions handed to the continuation engine.
#include <memory>
#include <string>

#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/stability/floquet.hpp"

namespace hbtrack {

struct StabilityOptions {
  StabilityMethod method = StabilityMethod::hill;
  int monodromy_steps = 2000;  // RK4 steps per period for the monodromy matrix
  HillSolver hill_solver = HillSolver::automatic;
  // Hill: where Hill's method is unreliable (a law that is not smooth, see
  // hill_needs_cross_check), the monodromy matrix decides instead (off: Hill alone).
  CrossCheck cross_check = CrossCheck::automatic;
  // An NFRC evaluates stability at every point (true), or, on models of more than 12 dofs, only
  // where the verdict can change (false): where the branch bends (every 0.1 rad of tangent turn),
  // where a PD/NS test function extrapolated from the last two evaluations heads for zero, on
  // both sides of a fold, and at least every 5th point; the points between two evaluated ones
  // that agree take their verdict ("bracketed"), and where the two disagree every point between
  // them is evaluated (continuation.hpp, BranchMonitor::may_skip_points).
  bool every_point = false;
  void validate() const;  // throws std::invalid_argument naming the field
  bool enabled() const { return method != StabilityMethod::none; }
};

FloquetResult floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, const StabilityOptions& options);

// Whether Hill's result `hill` at a point must be cross-checked by the monodromy matrix: an
// element law that is not smooth (Hill's exponents converge slowly there and the pairing of
// exponent families breaks down) on a model small enough for the monodromy matrix at every
// point, or a kept eigenvector far from the central harmonics.
bool hill_needs_cross_check(const HarmonicBalance& hbm, const FloquetResult& hill, const StabilityOptions& options);

class FloquetMonitor final : public BranchMonitor {
 public:
  FloquetMonitor(HarmonicBalance& hbm, StabilityOptions options);
  std::vector<SpecialPointType> types() const override { return {SpecialPointType::period_doubling, SpecialPointType::neimark_sacker}; }
  std::vector<double> test_functions(const BranchPoint& p) override;
  // A located PD/NS point must have its multiplier on the unit circle (to 1e-3, what Hill's
  // truncation leaves on a nonsmooth law); a bracketed one within 0.05 (the multipliers move by
  // about that between accepted points).
  bool confirm(SpecialPointType type, const BranchPoint& p, bool located) override;
  // The type read from the multipliers at p (crossing_type), whichever test function flipped.
  std::optional<SpecialPointType> classify(SpecialPointType type, const BranchPoint& p, bool located, std::string& decided_by) override;
  // With every_point false, on models where Hill's method alone decides (more dofs than the
  // time-domain cross-check takes): there it costs as much as the continuation. On small models
  // it costs little, and their bands can be one point wide (the two-dof contact example's PD band
  // at omega 0.667-0.687 holds one point).
  bool may_skip_points() const override { return may_skip_; }
  // The number of multipliers outside the unit circle, twice, plus one when unstable (the
  // count may stay 0 while an exponent sits just past the stability tolerance).
  int verdict(const BranchPoint& p) override;
  // Floquet result at p: reused when p is one of the last points evaluated (the engine
  // evaluates each accepted point before the observer sees it), computed otherwise.
  const FloquetResult& result_for(const BranchPoint& p);
  // Wall time spent computing Floquet results so far (the run's `timings.stability_s`).
  double seconds() const { return seconds_; }

 private:
  struct Entry {
    double lambda;
    Eigen::VectorXd u;
    FloquetResult result;
  };
  HarmonicBalance& hbm_;
  StabilityOptions options_;
  bool may_skip_ = false;
  std::vector<Entry> recent_;  // a few, newest last
  double seconds_ = 0;
};

}  // namespace hbtrack
