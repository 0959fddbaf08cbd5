#include "hbtrack/analysis/stability_monitor.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "hbtrack/stability/hill.hpp"
#include "hbtrack/stability/monodromy.hpp"
#include "hbtrack/stability/shooting.hpp"

namespace hbtrack {

void StabilityOptions::validate() const {
  if (monodromy_steps < 10 || monodromy_steps > 10000000)
    throw std::invalid_argument("stability.monodromy_steps: must be in [10, 10000000]");
}

namespace {
// The monodromy matrix at every point costs ~ monodromy_steps * 12 (2n)^3 flops: 0.1 s at 12
// dofs with the default 2000 steps, as much as the harmonic balance itself on such a model.
constexpr int kCrossCheckDofs = 12;
// A kept eigenvector whose energy centroid lies a harmonic or more off the centre is a truncation
// artefact rather than the resolved member of its family.
constexpr double kSpreadLimit = 1.0;

bool all_laws_smooth(const HarmonicBalance& hbm) {
  for (const auto& e : hbm.elements())
    if (!e->smoothness_limit().empty()) return false;
  return true;
}

// A history element without a time-stepping form cannot enter the monodromy matrix.
bool any_element_without_stepping(const HarmonicBalance& hbm) {
  for (const auto& e : hbm.elements())
    if (e->history_dependent() && e->history_state_size() == 0) return true;
  return false;
}

// Whether the time domain can check Hill on this model at every point.
bool cross_check_possible(const HarmonicBalance& hbm, const StabilityOptions& options) {
  return options.method == StabilityMethod::hill && options.cross_check != CrossCheck::off && hbm.model().dofs() <= kCrossCheckDofs &&
         !any_element_without_stepping(hbm);
}

// Whether the time domain decides every point whatever Hill finds there. Hysteretic (history)
// elements are not smooth either, and there Hill is worse than slow: the harmonic balance
// linearises the hysteresis for periodic perturbations only (lambda = 0), which can miss most
// of the friction's damping of a perturbation (docs/stability.md).
bool time_domain_decides(const HarmonicBalance& hbm, const StabilityOptions& options) {
  return cross_check_possible(hbm, options) && !all_laws_smooth(hbm);
}
}  // namespace

bool hill_needs_cross_check(const HarmonicBalance& hbm, const FloquetResult& hill, const StabilityOptions& options) {
  return time_domain_decides(hbm, options) || (cross_check_possible(hbm, options) && hill.centroid_spread > kSpreadLimit);
}

namespace {
// The multipliers of the orbit the equation of motion really has (shooting from the HBM state),
// or, where shooting does not converge or with history elements, the linearisation along the HBM
// orbit itself.
FloquetResult shooting_or_monodromy(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int steps) {
  // Shooting's state has no room for the sliders of history elements; the monodromy matrix
  // carries their variables along the HBM orbit (docs/stability.md).
  for (const auto& e : hbm.elements())
    if (e->history_dependent()) return monodromy_floquet(hbm, x, omega, steps);
  ShootingOutcome outcome;
  FloquetResult r = shooting_floquet(hbm, x, omega, steps, &outcome);
  return outcome.converged ? r : monodromy_floquet(hbm, x, omega, steps);
}
}  // namespace

FloquetResult floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, const StabilityOptions& options) {
  if (options.method == StabilityMethod::monodromy) return monodromy_floquet(hbm, x, omega, options.monodromy_steps);
  if (options.method == StabilityMethod::shooting) return shooting_or_monodromy(hbm, x, omega, options.monodromy_steps);
  // Hill's eigenvalues would be thrown away (on the 8-mass contact chain, a sixth of the run).
  if (time_domain_decides(hbm, options)) return shooting_or_monodromy(hbm, x, omega, options.monodromy_steps);
  FloquetResult hill = hill_floquet(hbm, x, omega, options.hill_solver);
  if (hill_needs_cross_check(hbm, hill, options)) return shooting_or_monodromy(hbm, x, omega, options.monodromy_steps);
  return hill;
}

FloquetMonitor::FloquetMonitor(HarmonicBalance& hbm, StabilityOptions options)
    : hbm_(hbm),
      options_(std::move(options)),
      may_skip_(!options_.every_point && options_.method == StabilityMethod::hill && hbm.model().dofs() > kCrossCheckDofs) {}

const FloquetResult& FloquetMonitor::result_for(const BranchPoint& p) {
  for (auto it = recent_.rbegin(); it != recent_.rend(); ++it)
    if (it->lambda == p.lambda && it->u.size() == p.u.size() && it->u == p.u) return it->result;
  if (recent_.size() >= 8) recent_.erase(recent_.begin());
  const auto start = std::chrono::steady_clock::now();
  recent_.push_back({p.lambda, p.u, floquet(hbm_, p.u, p.lambda, options_)});
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return recent_.back().result;
}

bool FloquetMonitor::confirm(SpecialPointType type, const BranchPoint& p, bool located) {
  return has_multiplier_on_unit_circle(result_for(p).multipliers, type, located ? 1e-3 : 0.05);
}

std::optional<SpecialPointType> FloquetMonitor::classify(SpecialPointType /*type*/, const BranchPoint& p, bool located,
                                                         std::string& decided_by) {
  const FloquetResult& r = result_for(p);
  decided_by = to_string(r.method);
  // Hill's truncation merges the two real multipliers of a period-doubling family into a pair
  // whose arguments miss pi by up to 0.006 rad (NLvib's two-dof contact example, H = 21); a
  // Neimark-Sacker pair that close to -1 would be the 1:2 strong resonance, where the two meet.
  // The monodromy matrix and shooting are real: their real eigenvalues are real to round-off.
  const double real_tolerance = r.method == StabilityMethod::hill ? 0.02 : 1e-6;
  std::optional<SpecialPointType> type = crossing_type(r.multipliers, located ? 1e-3 : 0.05, real_tolerance);
  // On a sampled C0 law the test function jumps a little between samples, and the secant may
  // stop a few 1e-3 off the circle: the bracket's tolerance still tells which multiplier crossed.
  if (!type && located) type = crossing_type(r.multipliers, 0.05, real_tolerance);
  if (type == SpecialPointType::limit_point) return std::nullopt;  // a multiplier through +1 is the engine's LP/BP test's
  return type;
}

int FloquetMonitor::verdict(const BranchPoint& p) {
  const FloquetResult& r = result_for(p);
  int outside = 0;
  for (Eigen::Index i = 0; i < r.multipliers.size(); ++i) outside += std::abs(r.multipliers(i)) > 1.0 ? 1 : 0;
  return 2 * outside + (r.stable ? 0 : 1);
}

std::vector<double> FloquetMonitor::test_functions(const BranchPoint& p) {
  const FloquetResult& r = result_for(p);
  return {period_doubling_test(r.multipliers), neimark_sacker_test(r.multipliers)};
}

}  // namespace hbtrack
