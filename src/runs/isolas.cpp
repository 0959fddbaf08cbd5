#include "hbtrack/runs/isolas.hpp"

#include <algorithm>
#include <cmath>

#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/runs/branch_tables.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

using nlohmann::json;

namespace {

// A branch found through a crossing, as a result of its own (plots, simulate --from, track).
json write_branch(const CaseDefinition& c, HarmonicBalance& hbm, const NfrcResult& branch, ResultSink& sink) {
  sink.open();
  BranchTables tables(c, hbm, sink, false);
  for (size_t i = 0; i < branch.recorded.size(); ++i) tables.append(branch.continuation.points[i], branch.recorded[i]);
  tables.append_special_points(branch.continuation.special_points);
  json summary = {{"verb", "isolas"}, {"options", options_json(c, hbm)}};
  add_nfrc_summary(summary, c, hbm, branch);
  sink.summary(summary);
  return summary;
}

}  // namespace

RunReport isolas(const CaseDefinition& c, const IsolaOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), o.parameter, "--param");
  // The CLI's --at refuses it as text; Python's at=nan reached the run and found no crossing.
  if (!std::isfinite(o.at)) throw CaseError("at: must be a finite number, got " + std::to_string(o.at));
  double lo = o.at, hi = o.at;
  for (const auto& curve : o.curves)
    for (const auto& p : curve) lo = std::min(lo, p.parameter), hi = std::max(hi, p.parameter);
  hbm.set_parameter(parameter, o.at);
  const FoldScales scales = tracking_scales(hbm, c.nfrc, std::max(hi - lo, 1e-300));
  sink.open();
  json summary = {{"verb", "isolas"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  json& options = summary["options"]["isolas"] = o.origin;
  options["parameter"] = o.parameter;
  options["at"] = o.at;
  sink.summary(summary);

  // Per branch, the part of the omega range its points span (an isola closes within it); the
  // point counts on across the branches.
  const double omega_lo = std::min(c.nfrc.omega_start, c.nfrc.omega_end), omega_hi = std::max(c.nfrc.omega_start, c.nfrc.omega_end);
  double low = 0, high = 0;
  int point = 0;
  const RecordedObserver observer = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    if (index == 0) low = high = p.lambda;
    low = std::min(low, p.lambda), high = std::max(high, p.lambda);
    return monitor.point({point++, p.lambda, p.lambda, 0, covered_fraction(omega_lo + high - low, omega_lo, omega_hi), &rec});
  };
  const std::vector<IsolaCandidate> found =
      compute_isolas(hbm, parameter, o.at, o.curves, scales, c.nfrc, c.outputs, !o.locate_only, observer);
  json crossings = json::array();
  int isola_count = 0;
  for (size_t k = 0; k < found.size(); ++k) {
    const IsolaCandidate& f = found[k];
    json j = {{"status", f.status}, {"omega", f.start.omega}, {"converged", f.start.converged}};
    if (f.same_as >= 0) j["same_as"] = f.same_as;
    if (f.start.converged) add_outputs(j, c, record_point(hbm, f.start.x, f.start.omega, c.outputs));
    if (f.status == "isola" || f.status == "open") {
      const std::string name = f.status == "isola" ? "isola_" + std::to_string(++isola_count) : "open_" + std::to_string(k + 1);
      const json branch = write_branch(c, hbm, f.branch, sink.child(name));
      j["folder"] = name;
      j["stop_reason"] = branch["stop_reason"];
      j["points"] = branch["points"];
      double omega_min = 1e300, omega_max = -1e300;
      for (const auto& p : f.branch.continuation.points)
        omega_min = std::min(omega_min, p.lambda), omega_max = std::max(omega_max, p.lambda);
      j["omega_range"] = {omega_min, omega_max};
      int unstable = 0;
      for (const auto& rec : f.branch.recorded) unstable += rec.stable == 0;
      j["unstable_points"] = unstable;
      j["special_points"] = branch["special_points"];
    }
    crossings.push_back(j);
  }
  summary["stop_reason"] = to_string(StopReason::completed);
  summary["crossings"] = crossings;
  summary["isolas"] = isola_count;
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  sink.summary(summary);
  char brief[160];
  std::snprintf(brief, sizeof brief, "%zu crossings of %s = %g, %d isolated branches", found.size(), o.parameter.c_str(), o.at,
                isola_count);
  return RunReport{summary, "", brief};
}

}  // namespace hbtrack::runs
