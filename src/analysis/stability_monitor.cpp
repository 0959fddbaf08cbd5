#include "hbtrack/analysis/stability_monitor.hpp"

#include <stdexcept>

#include "hbtrack/stability/hill.hpp"
#include "hbtrack/stability/monodromy.hpp"

namespace hbtrack {

void StabilityOptions::validate() const {
  if (method != "hill" && method != "monodromy" && method != "none")
    throw std::invalid_argument("stability.method: must be hill, monodromy or none, got '" + method + "'");
  if (hill_solver != "auto" && hill_solver != "dense" && hill_solver != "arnoldi")
    throw std::invalid_argument("stability.hill_solver: must be auto, dense or arnoldi, got '" + hill_solver + "'");
  if (monodromy_steps < 10 || monodromy_steps > 10000000)
    throw std::invalid_argument("stability.monodromy_steps: must be in [10, 10000000]");
}

FloquetResult floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, const StabilityOptions& options) {
  if (options.method == "monodromy") return monodromy_floquet(hbm, x, omega, options.monodromy_steps);
  return hill_floquet(hbm, x, omega, options.hill_solver);
}

const FloquetResult& FloquetMonitor::result_for(const BranchPoint& p) {
  for (auto it = recent_.rbegin(); it != recent_.rend(); ++it)
    if (it->lambda == p.lambda && it->u.size() == p.u.size() && it->u == p.u) return it->result;
  if (recent_.size() >= 8) recent_.erase(recent_.begin());
  recent_.push_back({p.lambda, p.u, floquet(hbm_, p.u, p.lambda, options_)});
  return recent_.back().result;
}

bool FloquetMonitor::confirm(const std::string& type, const BranchPoint& p, bool located) {
  return has_multiplier_on_unit_circle(result_for(p).multipliers, type, located ? 1e-3 : 0.05);
}

std::vector<double> FloquetMonitor::test_functions(const BranchPoint& p) {
  const FloquetResult& r = result_for(p);
  return {period_doubling_test(r.multipliers), neimark_sacker_test(r.multipliers)};
}

}  // namespace hbtrack
