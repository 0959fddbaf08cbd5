#include "hbtrack/runs/frc.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "hbtrack/analysis/adaptive_nfrc.hpp"
#include "hbtrack/results/continuation_state_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/runs/artefact_warnings.hpp"
#include "hbtrack/runs/branch_tables.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/runs/failure_advice.hpp"
#include "hbtrack/runs/friction_loop_gain_summary.hpp"
#include "hbtrack/runs/resume.hpp"
#include "hbtrack/runs/sticking_slider_warnings.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

namespace {

// The cluster's stretch of the branch computed again (the artefact check of
// special_point_clusters): from the branch point a few before its first limit point, with
// kRelocationSamplesFactor times the samples and steps kRelocationStepFactor times shorter,
// until it leaves the window of the cluster widened by its width on each side (or closes).
ClusterRecomputation cluster_recomputation(const CaseDefinition& c, const NfrcResult& r) {
  return [&c, &r](const std::vector<const SpecialPoint*>& cluster) -> std::optional<std::vector<double>> {
    const double lo = cluster.front()->lambda, hi = cluster.back()->lambda, width = hi - lo;
    int first = cluster.front()->index;
    for (const SpecialPoint* p : cluster) first = std::min(first, p->index);
    // Back along the branch to a point outside the widened window, where the branch is single.
    while (first > 0 && std::abs(r.continuation.points[static_cast<size_t>(first)].lambda - 0.5 * (lo + hi)) < 1.5 * width) --first;
    if (first + 1 >= static_cast<int>(r.continuation.points.size())) return std::nullopt;
    const BranchPoint& start = r.continuation.points[static_cast<size_t>(first)];
    const double next = r.continuation.points[static_cast<size_t>(first) + 1].lambda;
    CaseDefinition more = c;
    more.harmonic_balance.samples *= kRelocationSamplesFactor;
    // An adaptive run's points are padded to its largest H: the stretch is computed again there.
    const AdaptiveHarmonics& adaptive = c.harmonic_balance.adaptive;
    HarmonicBalance hbm = make_system_at(more, adaptive.enabled() ? adaptive.max : c.harmonic_balance.harmonics);
    NfrcOptions options = c.nfrc;
    options.stability.method = StabilityMethod::none;  // the limit points are the engine's own
    options.continuation.step /= kRelocationStepFactor;
    options.continuation.step_max /= kRelocationStepFactor;
    options.continuation.max_points = 4000;
    ParameterWindow window{lo - width, hi + width, next >= start.lambda ? 1 : -1, true};
    window.lambda_min = std::min(window.lambda_min, start.lambda - width);
    window.lambda_max = std::max(window.lambda_max, start.lambda + width);
    try {
      const NfrcResult again = compute_branch(hbm, options, {}, start.u, start.lambda, window);
      std::vector<double> omegas;
      for (const SpecialPoint& p : again.continuation.special_points)
        if (p.type == SpecialPointType::limit_point && p.lambda >= lo - width && p.lambda <= hi + width) omegas.push_back(p.lambda);
      return omegas;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  };
}

}  // namespace

using nlohmann::json;

RunReport frc(const CaseDefinition& c, const FrcOptions& options, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  const AdaptiveHarmonics& adaptive = c.harmonic_balance.adaptive;
  // The systems an adaptive run visits, built once each; the tables are written at its largest
  // H (its points padded with zeros), which is also `hbm` below.
  std::map<int, HarmonicBalance> systems;
  const SystemWithHarmonics system_with = [&](int harmonics) -> HarmonicBalance& {
    auto found = systems.find(harmonics);
    if (found == systems.end()) found = systems.emplace(harmonics, make_system_at(c, harmonics)).first;
    return found->second;
  };
  HarmonicBalance hbm = adaptive.enabled() ? system_with(adaptive.max) : make_system(c);
  if (adaptive.enabled() && sink.resuming())
    throw CaseError("--resume: " + sink.location() +
                    " is an adaptive-harmonics run (harmonic_balance.adaptive), which does not resume: run it again");
  if (options.start)
    options.start->require_unknowns(adaptive.enabled() ? system_with(c.harmonic_balance.harmonics).unknowns() : hbm.unknowns());
  json summary = {{"verb", "frc"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  if (!options.started_from.is_null()) summary["started_from"] = options.started_from;
  // Static, so known before the first point: a stopped run has it too.
  const double from = options.start ? options.start->omega : c.nfrc.omega_start, end = c.nfrc.omega_end;
  const std::vector<FrictionLoopGain> gains = case_friction_loop_gains(c, from, end);
  std::vector<std::string> warnings = friction_loop_gain_warnings(gains);
  if (!gains.empty()) summary["friction_loop_gain"] = friction_loop_gain_json(gains);
  if (!warnings.empty()) summary["warnings"] = warnings;
  const json settings = branch_settings(summary["options"]);
  std::optional<SavedContinuation> resumed;
  if (sink.resuming())
    resumed = checkpoint_to_resume(sink, {StopReason::reached_end, StopReason::left_range, StopReason::closed}, settings,
                                   read_continuation_state);
  // Checked before the folder is touched: the engine refused it later, exit 3 and the summary
  // left at running.
  if (resumed && resumed->state.x.size() != hbm.unknowns() + 1)
    throw CaseError("--resume: " + sink.checkpoint_path() + ": the state holds " + std::to_string(resumed->state.x.size() - 1) +
                    " unknowns, this case " + std::to_string(hbm.unknowns()));
  sink.open();
  // A resumed run appends to the tables the checkpoint covers.
  const int rows_kept = resumed ? resumed->state.points : 0;
  BranchTables tables(c, hbm, sink, options.element_forces, resumed.has_value(), rows_kept);
  if (resumed) summary["resumed_at_point"] = rows_kept;
  sink.summary(summary);

  ContinuationRestart restart;
  if (resumed) restart.resume_from = &resumed->state;
  // After every accepted point (and step-size update): what a resumed run goes on from.
  // The stability methods of the points so far, kept in the checkpoint: r.recorded below holds
  // this run's points only, and a resumed run's summary counted those alone.
  const json earlier_methods = resumed ? resumed->tallies.value("stability_methods", json::object()) : json::object();
  json methods = earlier_methods;
  const std::string checkpoint = sink.checkpoint_path();
  if (!checkpoint.empty())
    restart.on_state = [&](const ContinuationState& state) {
      write_continuation_state(checkpoint, state, settings, {{"stability_methods", methods}});
    };
  Coverage coverage = Coverage::one_way(from, end);
  const RecordedObserver record = [&](const BranchPoint& p, const RecordedPoint& rec, int index) {
    tables.append(p, rec);
    if (!rec.stability_method.empty()) methods[rec.stability_method] = methods.value(rec.stability_method, 0) + 1;
    return monitor.point({index, p.lambda, p.lambda, 0, coverage.add(p.lambda), &rec});
  };
  NfrcResult r;
  if (adaptive.enabled()) {
    AdaptiveStart start{c.harmonic_balance.harmonics, {}, c.nfrc.omega_start, {}};
    if (options.start)
      start = {
          c.harmonic_balance.harmonics, options.start->x, from, {std::min(from, end), std::max(from, end), end > from ? 1 : -1, false}};
    r = compute_adaptive_nfrc(system_with, adaptive, start, c.nfrc, c.outputs, record);
  } else if (!options.start) {
    r = compute_nfrc(hbm, c.nfrc, c.outputs, record, restart);
  } else {
    const ParameterWindow window{std::min(from, end), std::max(from, end), end > from ? 1 : -1, false};
    r = compute_branch(hbm, c.nfrc, c.outputs, options.start->x, from, window, record, restart);
  }
  const auto& s = r.continuation.summary;
  const std::string stop_reason = to_string(monitor.stop_reason(s.stop_reason));
  add_nfrc_summary(summary, c, hbm, r);
  if (adaptive.enabled()) add_adaptive_harmonics_summary(summary, r, hbm.retained_dofs());
  if (summary.contains("stability_methods"))
    for (const auto& [method, count] : earlier_methods.items()) {
      json& points = summary["stability_methods"]["points"];
      if (count.is_number_integer()) points[method] = points.value(method, 0) + count.get<int>();
    }
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", s.wall_s}, {"stability_s", r.stability_s}};
  tables.append_special_points(r.continuation.special_points);
  const double omega_range = std::abs(c.nfrc.omega_end - c.nfrc.omega_start);
  for (std::string& w : special_point_clusters(r.continuation.special_points, omega_range, cluster_recomputation(c, r)))
    warnings.push_back(std::move(w));
  for (std::string& w : unconfirmed_hill_bifurcations(r.continuation.special_points, first_nonsmooth_element(c), hbm.basis().harmonics()))
    warnings.push_back(std::move(w));
  for (std::string& w : sticking_slider_warnings(hbm, r.continuation.points)) warnings.push_back(std::move(w));
  summary["warnings"] = warnings;
  const double last_omega = r.recorded.empty() ? from : r.recorded.back().omega;
  if (!r.continuation.success()) summary["advice"] = continuation_failure_advice(s, c.nfrc.continuation, last_omega);
  sink.summary(summary);

  RunReport report{summary};
  if (!r.continuation.success())
    report.failure = "continuation stopped: " + stop_reason + " after " + std::to_string(s.points) + " points (kept in " + sink.location() +
                     "): " + summary["advice"].get<std::string>();
  else
    report.brief = std::to_string(s.points) + " points, " + std::to_string(r.continuation.special_points.size()) + " special points, " +
                   std::to_string(s.newton_iterations) + " Newton iterations";
  return report;
}

}  // namespace hbtrack::runs
