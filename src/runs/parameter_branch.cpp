#include "hbtrack/runs/parameter_branch.hpp"

#include <cmath>
#include <stdexcept>

#include "hbtrack/analysis/parameter_continuation.hpp"
#include "hbtrack/results/parameter_tables.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

using nlohmann::json;

RunReport continue_in_parameter(const CaseDefinition& c, const ParameterBranchOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  if (!(o.omega > 0) || !std::isfinite(o.omega)) throw CaseError("--omega: must be > 0 and finite");
  if (!std::isfinite(o.start) || !std::isfinite(o.end) || o.start == o.end) throw CaseError("--range: LO and HI must be finite and differ");
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), o.parameter, "--param");
  json summary = {{"verb", "continue"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  summary["options"]["continue"] = parameter_continuation_options(o.parameter, o.omega, o.start, o.end);
  sink.open();
  const auto branch = sink.table("branch", parameter_branch_header(c, o.parameter));
  // Every dof's harmonics at each point's own parameter value: the condensed dofs' recovery
  // depends on it.
  const auto states = sink.table("states", dof_state_header(hbm));
  std::unique_ptr<TableSink> unknowns;
  if (sink.keeps_unknowns()) unknowns = sink.table("unknowns", state_header(hbm.unknowns()));
  sink.summary(summary);

  Coverage coverage = Coverage::one_way(o.start, o.end);
  ParameterBranchResult r;
  try {
    r = continue_in_parameter(hbm, parameter, o.omega, o.start, o.end, c.nfrc, c.outputs,
                              [&](const BranchPoint& p, const ParameterBranchPoint& point, int index) {
                                branch->append(parameter_branch_row(point));
                                states->append(dof_state_row(hbm, o.omega, p.u, parameter, p.lambda));
                                if (unknowns) unknowns->append(state_row(o.omega, p.u));
                                return monitor.point({index, o.omega, p.lambda, 0, coverage.add(p.lambda), &point.recorded});
                              });
  } catch (const WriteFailed&) {
    throw;  // the disk, not the continuation: no summary can be written either
  } catch (const std::runtime_error& e) {
    summary["stop_reason"] = to_string(StopReason::no_convergence);
    summary["points"] = 0;
    sink.summary(summary);
    throw;
  }
  const auto& s = r.continuation.summary;
  const std::string stop_reason = to_string(monitor.stop_reason(s.stop_reason));
  add_parameter_branch_summary(summary, c, hbm, r, parameter);
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", s.wall_s}};
  const auto special_states = sink.table("special_states", dof_state_header(hbm));
  std::unique_ptr<TableSink> special_unknowns;
  if (sink.keeps_unknowns()) special_unknowns = sink.table("special_unknowns", state_header(hbm.unknowns()));
  for (const auto& sp : r.continuation.special_points) {
    special_states->append(dof_state_row(hbm, o.omega, sp.u, parameter, sp.lambda));
    if (special_unknowns) special_unknowns->append(state_row(o.omega, sp.u));
  }
  sink.summary(summary);
  RunReport report{summary};
  if (!r.continuation.success())
    report.failure =
        "continuation stopped: " + stop_reason + " after " + std::to_string(s.points) + " points (kept in " + sink.location() + ")";
  else
    report.brief = std::to_string(s.points) + " points, " + std::to_string(r.continuation.special_points.size()) + " special points, " +
                   std::to_string(s.newton_iterations) + " Newton iterations";
  return report;
}

}  // namespace hbtrack::runs
