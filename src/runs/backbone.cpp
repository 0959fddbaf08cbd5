#include "hbtrack/runs/backbone.hpp"

#include <cmath>
#include <stdexcept>

#include "hbtrack/model/damping.hpp"
#include "hbtrack/results/backbone_tables.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

using nlohmann::json;

RunReport backbone(CaseDefinition c, BackboneOptions options, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  if (!(options.amplitude_start > 0) || !(options.amplitude_end > options.amplitude_start) || !std::isfinite(options.amplitude_end))
    throw CaseError("--range: must be LO:HI with 0 < LO < HI, finite");
  if (options.mode < 1 || options.mode > c.model.dofs())
    throw CaseError("--mode: " + std::to_string(options.mode) + " must be from 1 to the model's " + std::to_string(c.model.dofs()) +
                    " modes");
  c.harmonic_balance.condensation = Condensation::none;
  HarmonicBalance hbm = make_system(c);
  // What compute_backbone refuses, refused before the folder exists (it was exit 3 after it).
  try {
    hbm.refuse_residual_elements("the backbone (EPMC)");
  } catch (const std::invalid_argument& e) {
    throw CaseError(std::string("elements: ") + e.what());
  }
  if (hbm.subharmonic() != 1 || hbm.basis().cosine_index(1) < 0)
    throw CaseError("harmonic_balance: the backbone needs harmonic 1 among the harmonics and subharmonic = 1");
  const NormalModes modes = normal_modes(c.model.mass, c.model.stiffness);
  if (!(modes.frequencies(options.mode - 1) > 1e-6 * modes.frequencies.maxCoeff()))
    throw CaseError("--mode: mode " + std::to_string(options.mode) +
                    " has no positive frequency (a rigid-body mode): follow a flexible one");
  options.continuation = c.nfrc.continuation;
  json summary = {{"verb", "backbone"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  summary["options"]["backbone"] = backbone_options_json(options);
  sink.open();
  const auto branch = sink.table("branch", backbone_header(c, hbm.basis().harmonic_numbers()));
  const auto states = sink.table("states", dof_state_header(hbm));
  std::unique_ptr<TableSink> unknowns;
  if (sink.keeps_unknowns()) unknowns = sink.table("unknowns", backbone_state_header(hbm.unknowns()));
  sink.summary(summary);

  Coverage coverage = Coverage::one_way(std::log10(options.amplitude_start), std::log10(options.amplitude_end));  // steps in log10(a)
  BackboneResult r;
  try {
    r = compute_backbone(hbm, options, c.outputs, [&](const BranchPoint& p, const BackbonePoint& point, int index) {
      branch->append(backbone_row(point));
      states->append(dof_state_row(hbm, point.omega, point.amplitude * p.u.head(hbm.unknowns())));
      if (unknowns) unknowns->append(backbone_state_row(point, p.u, hbm.unknowns()));
      return monitor.point({index, point.omega, point.amplitude, 0, coverage.add(p.lambda), &point.recorded});
    });
  } catch (const std::runtime_error& e) {
    summary["stop_reason"] = to_string(StopReason::no_convergence);
    summary["points"] = 0;
    sink.summary(summary);
    throw;
  }
  const auto& s = r.continuation.summary;
  const std::string stop_reason = to_string(monitor.stop_reason(s.stop_reason));
  add_backbone_summary(summary, c, hbm, r);
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", s.wall_s}};
  sink.summary(summary);
  RunReport report{summary};
  if (!r.continuation.success()) {
    report.failure =
        "backbone stopped: " + stop_reason + " after " + std::to_string(s.points) + " points (kept in " + sink.location() + ")";
  } else {
    char brief[160];
    std::snprintf(brief, sizeof brief, "mode %d, %d points, omega %.6g -> %.6g", options.mode, s.points, r.points.front().omega,
                  r.points.back().omega);
    report.brief = brief;
  }
  return report;
}

}  // namespace hbtrack::runs
