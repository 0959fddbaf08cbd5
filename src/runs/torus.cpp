#include "hbtrack/runs/torus.hpp"

#include <stdexcept>

#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/torus_tables.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

using nlohmann::json;

namespace {
// A dense Jacobian of 512 MB; a run holds about four matrices of that order (rotor 67's torus, 5734
// unknowns: 1.1 GB resident).
constexpr long kMaxTorusUnknowns = 8000;
constexpr long kMaxTorusGridEntries = 1L << 23;  // 64 MB per grid matrix, four of them

// The run's options checked (CaseError naming the option) and resolved.
TorusOptions torus_options(const CaseDefinition& c, const HarmonicBalance& hbm, const TorusRunOptions& o) {
  if (!(o.omega_min < o.omega_max)) throw CaseError(o.range_name + ": must be LO:HI with LO < HI");
  if (!(o.omega_min < o.start.omega && o.start.omega < o.omega_max))
    throw CaseError(o.range_name + ": must contain the NS point's omega = " + std::to_string(o.start.omega));
  if (o.h1 < 0 || o.h2 < 1) throw CaseError(o.harmonics_name + ": must be H1,H2 with H1 >= 1 (or 0: the case's H) and H2 >= 1");
  if (o.n1 < 0 || o.n2 < 0) throw CaseError(o.samples_name + ": must be N1,N2 >= 0 (0: the default)");
  if (!(o.start_fraction > 0 && o.start_fraction < 1)) throw CaseError("start_fraction: must be in (0, 1)");
  TorusOptions t;
  t.h1 = o.h1;
  t.h2 = o.h2;
  t.n1 = o.n1;
  t.n2 = o.n2;
  t.omega_min = o.omega_min;
  t.omega_max = o.omega_max;
  t.start_fraction = o.start_fraction;
  t.continuation = c.nfrc.continuation;
  t = resolved_torus_options(hbm, t);
  if (t.h1 > 64 || t.h2 > 64) throw CaseError(o.harmonics_name + ": at most 64 each (a dense 2-D basis)");
  if (t.n1 < 2 * t.h1 + 1 || t.n2 < 2 * t.h2 + 1)
    throw CaseError(o.samples_name + ": must be N1 >= 2 H1 + 1 = " + std::to_string(2 * t.h1 + 1) +
                    " and N2 >= 2 H2 + 1 = " + std::to_string(2 * t.h2 + 1));
  // Everything is dense: the Jacobian (unknowns^2) and the grid matrices (4 x grid x coefficients).
  const long coefficients = 1 + 2 * (t.h2 + static_cast<long>(t.h1) * (2 * t.h2 + 1));
  const long dofs = static_cast<long>(torus_retained_dofs(hbm, c.outputs).size());
  const long unknowns = coefficients * dofs + 1, grid = static_cast<long>(t.n1) * t.n2;
  if (unknowns > kMaxTorusUnknowns)
    throw CaseError(o.harmonics_name + ": the torus would have " + std::to_string(unknowns) + " unknowns (" + std::to_string(dofs) +
                    " retained dofs x " + std::to_string(coefficients) + " coefficients), at most " + std::to_string(kMaxTorusUnknowns) +
                    " (its Jacobian is dense): fewer harmonics, or a smaller model");
  if (grid * coefficients > kMaxTorusGridEntries)
    throw CaseError(o.samples_name + ": the grid of " + std::to_string(grid) + " samples times " + std::to_string(coefficients) +
                    " coefficients is above " + std::to_string(kMaxTorusGridEntries) + " (dense matrices): fewer samples or harmonics");
  return t;
}
}  // namespace

RunReport torus(const CaseDefinition& c, const TorusRunOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  HarmonicBalance hbm = make_system(c);
  o.start.require_unknowns(hbm.unknowns());
  const TorusOptions options = torus_options(c, hbm, o);
  // What the torus cannot take is bad input: checked before the folder is touched.
  try {
    const FoldScales unit;
    TorusSystem check(hbm, TorusBasis(options.h1, options.h2, options.n1, options.n2), unit, torus_retained_dofs(hbm, c.outputs));
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
  std::vector<std::string> retained_names;
  for (const int d : torus_retained_dofs(hbm, c.outputs)) retained_names.push_back(c.model.dof_names[static_cast<size_t>(d)]);
  json summary = {{"verb", "torus"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  summary["options"]["torus"] = o.origin;
  summary["outputs"] = outputs_json(c);
  sink.open();
  const auto branch = sink.table("branch", torus_branch_header(c));
  const auto states = sink.table("states", torus_state_header(TorusBasis(options.h1, options.h2, options.n1, options.n2), retained_names));
  sink.summary(summary);

  const FoldScales scales = tracking_scales(hbm, c.nfrc, options.omega_max - options.omega_min);
  Coverage coverage = Coverage::one_way(options.omega_min, options.omega_max);
  TorusBranchResult r;
  try {
    r = torus_branch(hbm, o.start.x, o.start.omega, scales, options, c.outputs, [&](const TorusPoint& p, int index) {
      branch->append(torus_branch_row(p));
      states->append(torus_state_row(p));
      return monitor.point({index, p.omega, p.omega, 0, coverage.add(p.omega), nullptr});
    });
  } catch (const std::runtime_error& e) {
    summary["stop_reason"] = to_string(StopReason::no_convergence_at_start);
    summary["points"] = 0;
    sink.summary(summary);
    throw;
  }
  add_torus_summary(summary, c, r, options);
  const std::string stop_reason = to_string(monitor.stop_reason(r.stop_reason));
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", r.summary.wall_s}};
  sink.summary(summary);
  RunReport report{summary};
  const std::string end = r.points.empty() ? "" : " at omega = " + std::to_string(r.points.back().omega);
  if (!r.success())
    report.failure = "torus branch stopped: " + stop_reason + " after " + std::to_string(r.points.size()) + " points" + end + " (kept in " +
                     sink.location() + ")";
  else
    report.brief =
        std::to_string(r.points.size()) + " points from the NS point at omega = " + std::to_string(r.omega_ns) + ", " + stop_reason + end;
  return report;
}

}  // namespace hbtrack::runs
