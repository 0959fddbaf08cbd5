#include "hbtrack/runs/switch_branch.hpp"

#include <algorithm>
#include <stdexcept>

#include "hbtrack/analysis/branch_switching.hpp"
#include "hbtrack/analysis/period_doubling.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/runs/branch_tables.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

using nlohmann::json;

RunReport switch_branch(const CaseDefinition& period_one, const SwitchOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  if (o.type != SpecialPointType::branch_point && o.type != SpecialPointType::period_doubling)
    throw CaseError("--point: a BP or a PD, got a " + to_string(o.type));
  if (o.type == SpecialPointType::period_doubling && period_one.harmonic_balance.subharmonic != 1)
    throw CaseError("--point: already a period-doubled branch (subharmonic " + std::to_string(period_one.harmonic_balance.subharmonic) +
                    "); switch from a period-T NFRC");
  HarmonicBalance hbm = make_system(period_one);
  for (const StartPoint* p : {&o.at, &o.before, &o.after}) p->require_unknowns(hbm.unknowns());
  CaseDefinition c = period_one;
  if (o.type == SpecialPointType::period_doubling)
    c.harmonic_balance = period_doubled_options(period_one.harmonic_balance);  // the branch at omega / 2
  HarmonicBalance system = make_system(c);
  Eigen::VectorXd known(hbm.unknowns() + 1);
  known.head(hbm.unknowns()) = o.after.x - o.before.x;
  known(hbm.unknowns()) = o.after.omega - o.before.omega;
  sink.open();
  json summary = {{"verb", "switch"}, {"options", options_json(c, system)}, {"stop_reason", to_string(StopReason::running)}};
  json& options = summary["options"]["switch"] = o.origin;
  options.update({{"point", o.point}, {"type", to_string(o.type)}, {"omega", o.at.omega}});
  sink.summary(summary);

  // Each of the two legs counts for half, by the part of the omega range between the point and
  // the end the leg heads for that it has covered.
  const double omega = o.at.omega;
  const double lo = std::min(c.nfrc.omega_start, c.nfrc.omega_end), hi = std::max(c.nfrc.omega_start, c.nfrc.omega_end);
  int legs_started = 0, reported = 0;
  Coverage coverage = Coverage::one_way(omega, omega);
  const RecordedObserver observer = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    if (index == 0) {  // a new leg, its direction not known yet
      ++legs_started;
      coverage = Coverage::one_way(omega, omega);
    }
    if (index == 1) coverage = Coverage::one_way(omega, p.lambda > omega ? hi : lo);  // the leg's direction
    return monitor.point({reported++, p.lambda, p.lambda, 0, 0.5 * (std::min(legs_started, 2) - 1 + coverage.add(p.lambda)), &rec});
  };
  SwitchedBranch s;
  try {
    s = o.type == SpecialPointType::period_doubling
            ? switch_at_period_doubling(system, hbm.basis(), c.nfrc, c.outputs, o.at.x, omega, known, observer)
            : switch_at_branch_point(system, c.nfrc, c.outputs, o.at.x, omega, known, true, false, observer);
  } catch (const WriteFailed&) {
    throw;  // the disk, not the continuation: no summary can be written either
  } catch (const std::runtime_error&) {
    summary["stop_reason"] = to_string(StopReason::no_convergence);
    sink.summary(summary);
    throw;
  }
  // One piece: the `through` leg reversed, then the `away` leg without its first point (shared).
  BranchTables tables(c, system, sink, false);
  const int through = static_cast<int>(s.through.recorded.size());
  for (int i = through - 1; i >= 0; --i)
    tables.append(s.through.continuation.points[static_cast<size_t>(i)], s.through.recorded[static_cast<size_t>(i)]);
  const int shift = through > 0 ? through - 1 : 0;  // row of the away leg's point i: shift + i
  for (size_t i = through > 0 ? 1 : 0; i < s.away.recorded.size(); ++i) tables.append(s.away.continuation.points[i], s.away.recorded[i]);
  json points = json::array();
  std::vector<SpecialPoint> special;
  for (const auto* leg : {&s.through, &s.away})
    for (const auto& p : leg->continuation.special_points) {
      json j = {{"type", to_string(p.type)},
                {"index", leg == &s.through ? through - 1 - p.index : shift + p.index},
                {"omega", p.lambda},
                {"located", p.located}};
      j["parameters"] = summary["options"]["parameters"];
      add_outputs(j, c, record_point(system, p.u, p.lambda, c.outputs));
      points.push_back(j);
      special.push_back(p);
    }
  tables.append_special_points(special);
  const auto& a = s.away.continuation.summary;
  const auto& b = s.through.continuation.summary;
  summary["special_points"] = points;
  summary["outputs"] = outputs_json(c);
  summary["points"] = shift + static_cast<int>(s.away.recorded.size());
  summary["newton_iterations"] = a.newton_iterations + b.newton_iterations;
  summary["failed_steps"] = a.failed_steps + b.failed_steps;
  summary["step_halvings"] = a.step_halvings + b.step_halvings;
  summary["legs"] = {{{"name", "through"}, {"stop_reason", to_string(b.stop_reason)}, {"points", b.points}},
                     {{"name", "away"}, {"stop_reason", to_string(a.stop_reason)}, {"points", a.points}}};
  // A period-doubled leg ends where it rejoins the period-T branch (at a PD of the band).
  const bool away_ok = s.away.continuation.success() || a.stop_reason == StopReason::rejoined;
  const bool ok = away_ok && (s.through.continuation.success() || b.stop_reason == StopReason::rejoined);
  summary["stop_reason"] = to_string(ok ? StopReason::completed : monitor.stop_reason(away_ok ? b.stop_reason : a.stop_reason));
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  sink.summary(summary);
  RunReport report{summary};
  if (!ok)
    report.failure = "switch: a leg stopped: " + summary["stop_reason"].get<std::string>() + " (kept in " + sink.location() + ")";
  else
    report.brief = std::to_string(summary["points"].get<int>()) + " points, " + std::to_string(points.size()) + " special points";
  return report;
}

}  // namespace hbtrack::runs
