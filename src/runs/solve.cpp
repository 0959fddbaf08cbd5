// `solve`: one periodic solution at a fixed frequency (runs/frc.hpp).
#include <cmath>

#include "hbtrack/analysis/stability_monitor.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/runs/frc.hpp"

namespace hbtrack::runs {

using nlohmann::json;

RunReport solve(const CaseDefinition& c, double omega, ResultSink& sink) {
  const auto t0 = RunClock::now();
  if (!(omega > 0) || !std::isfinite(omega)) throw CaseError("--omega: must be > 0 and finite");
  HarmonicBalance hbm = make_system(c);
  sink.open();
  const auto& co = c.nfrc.continuation;
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, co.tolerance, 4 * co.max_iterations);
  json summary = {{"verb", "solve"},
                  {"options", options_json(c, hbm)},
                  {"omega", omega},
                  {"converged", s.converged},
                  {"stop_reason", to_string(s.converged ? StopReason::converged : StopReason::no_convergence)},
                  {"points", s.converged ? 1 : 0},
                  // A failed solve spent every iteration it was allowed (the message says so).
                  {"newton_iterations", s.converged ? s.newton_iterations : 4 * co.max_iterations},
                  {"failed_steps", s.converged ? 0 : 1},
                  {"special_points", json::array()}};
  if (s.converged) {
    RecordedPoint rec = s.recorded;
    if (c.nfrc.stability.enabled()) {
      const FloquetResult f = floquet(hbm, s.x, omega, c.nfrc.stability);
      rec.stable = f.stable ? 1 : 0;
      summary["stable"] = f.stable;
      summary["max_floquet_real"] = f.max_real;
      json multipliers = json::array();
      for (Eigen::Index i = 0; i < f.multipliers.size(); ++i) multipliers.push_back({f.multipliers(i).real(), f.multipliers(i).imag()});
      summary["floquet_multipliers"] = multipliers;
    }
    sink.table("branch", branch_header(c))->append(branch_row(rec));
    sink.table("states", dof_state_header(hbm))->append(dof_state_row(hbm, omega, s.x));
    if (sink.keeps_unknowns()) sink.table("unknowns", state_header(hbm.unknowns()))->append(state_row(omega, s.x));
    add_outputs(summary, c, s.recorded);
  }
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  sink.summary(summary);
  RunReport report{summary};
  if (!s.converged)
    report.failure = "Newton did not converge at omega = " + std::to_string(omega) + " in " + std::to_string(4 * co.max_iterations) +
                     " iterations from the linear solution: solve nearer the linear regime, or raise continuation.max_iterations";
  else
    report.brief = "converged in " + std::to_string(s.newton_iterations) + " Newton iterations";
  return report;
}

}  // namespace hbtrack::runs
