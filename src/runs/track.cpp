#include "hbtrack/runs/track.hpp"

#include <algorithm>
#include <optional>

#include "hbtrack/results/continuation_state_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/runs/artefact_warnings.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/runs/resume.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::runs {

using nlohmann::json;

namespace {

// After a failed tracking run: the elements whose law the fold systems cannot differentiate, the
// likely cause ("" when every law is smooth).
std::string smoothness_hint(const HarmonicBalance& hbm, TrackedPoint tracked) {
  std::string hint;
  for (size_t i = 0; i < hbm.elements().size(); ++i) {
    const std::string limit = hbm.elements()[i]->smoothness_limit();
    if (limit.empty()) continue;
    hint += hint.empty() ? "; " : ", ";
    hint += "elements[" + std::to_string(i) + "] (" + hbm.elements()[i]->type() + "): " + limit;
  }
  if (!hint.empty())
    hint += tracked == TrackedPoint::limit_point ? ": limit-point tracking needs a law with a smooth Jacobian (law = \"sqrt\")"
                                                 : ": NS and PD tracking need a law whose Jacobian is C1 (law = \"sqrt\")";
  return hint;
}

std::vector<std::string> tracking_warnings(const FoldTrackingResult& r, const TrackOptions& o, double start_omega) {
  double omega_low = start_omega, omega_high = start_omega;
  for (const FoldCurvePoint& p : r.points) omega_low = std::min(omega_low, p.omega), omega_high = std::max(omega_high, p.omega);
  std::vector<std::string> warnings =
      extremum_pairs_below_resolution(r.extrema, o.parameter, o.parameter_max - o.parameter_min, omega_high - omega_low);
  for (const ContinuationSummary& leg : r.legs)
    if (leg.stop_reason == StopReason::max_points)
      warnings.push_back("a leg stopped at continuation.max_points after " + std::to_string(leg.points) +
                         " points, before the range's end: the curve is incomplete (rerun with a larger --set continuation.max_points)");
  return warnings;
}

// The closing line's account of the legs: "both ways to the range" only when both got there (a leg
// cut by max_points left an incomplete curve, and the line said otherwise).
std::string how_the_legs_ended(const FoldTrackingResult& r) {
  if (r.closed) return "closed";
  std::string text;
  bool both_to_the_range = true;
  for (size_t i = 0; i < r.legs.size(); ++i) {
    const StopReason reason = r.legs[i].stop_reason;
    both_to_the_range = both_to_the_range && (reason == StopReason::reached_end || reason == StopReason::left_range);
    text += (i == 0 ? "leg " : ", leg ") + std::to_string(i + 1) + " " + to_string(reason);
  }
  return both_to_the_range ? "both ways to the range" : text;
}

}  // namespace

RunReport track(const CaseDefinition& c, const TrackOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  if (!(o.parameter_min < o.parameter_max)) throw CaseError(o.range_name + ": must be LO:HI with LO < HI");
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), o.parameter, o.parameter_name);
  const double start_value = hbm.parameters().value(parameter);
  if (!(o.parameter_min <= start_value && start_value <= o.parameter_max))
    throw CaseError(
        o.range_name + ": must contain " + o.parameter + " = " + std::to_string(start_value) + " of the " +
        (o.tracked == TrackedPoint::limit_point ? std::string("limit point") : to_string(special_point_type(o.tracked)) + " point"));
  o.start.require_unknowns(hbm.unknowns());
  FoldTrackingOptions tracking;
  tracking.parameter_min = o.parameter_min;
  tracking.parameter_max = o.parameter_max;
  tracking.method = o.method;
  tracking.tracked = o.tracked;
  tracking.continuation = c.nfrc.continuation;

  json summary = {{"verb", "track"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  json& options = summary["options"]["tracking"] = o.origin;
  options["parameter"] = o.parameter;
  options["method"] = to_string(o.method);
  options["point"] = to_string(special_point_type(o.tracked));
  options["range"] = {o.parameter_min, o.parameter_max};
  const json settings = branch_settings(summary["options"]);
  std::optional<SavedTracking> resumed;
  if (sink.resuming()) resumed = checkpoint_to_resume(sink, {StopReason::completed, StopReason::closed}, settings, read_tracking_state);
  // Checked before the folder is touched, as frc's: the engine got vectors of another size.
  if (resumed)
    if (const std::string misfit = tracking_state_misfit(resumed->state, tracking, hbm.unknowns()); !misfit.empty())
      throw CaseError("--resume: " + sink.checkpoint_path() + ": " + misfit);
  sink.open();
  const int rows_kept = resumed ? resumed->state.curve_points : 0;
  const TableStart start{resumed.has_value(), rows_kept};
  const std::vector<std::string> leading{"leg", "omega", o.parameter};
  std::vector<std::string> state_columns = leading, unknown_columns = leading;
  for (const std::string& column : dof_state_columns(hbm)) state_columns.push_back(column);
  for (const std::string& column : state_header(hbm.unknowns()))
    if (column != "omega") unknown_columns.push_back(column);
  const auto branch = sink.table("branch", tracking_header(c, o.parameter, o.tracked), start);
  const auto states = sink.table("states", state_columns, start);
  std::unique_ptr<TableSink> unknowns;
  if (sink.keeps_unknowns()) unknowns = sink.table("unknowns", unknown_columns, start);
  if (resumed) summary["resumed_at_point"] = rows_kept;
  sink.summary(summary);

  const FoldScales scales = tracking_scales(hbm, c.nfrc, o.parameter_max - o.parameter_min);
  FoldTrackingRestart restart;
  if (resumed) restart.resume_from = &resumed->state;
  // Between two steps: what a resumed run goes on from.
  const std::string checkpoint = sink.checkpoint_path();
  if (!checkpoint.empty()) restart.on_state = [&](const FoldTrackingState& state) { write_tracking_state(checkpoint, state, settings); };
  Coverage coverage = Coverage::two_legs(o.parameter_min, o.parameter_max, start_value);
  const FoldTrackingResult r = track_fold(
      hbm, parameter, o.start.x, o.start.omega, scales, tracking, c.outputs,
      [&](const FoldCurvePoint& p, int index) {
        branch->append(tracking_row(p, o.tracked));
        std::vector<double> row{static_cast<double>(p.leg), p.omega, p.parameter};
        const std::vector<double> dofs = dof_state_values(hbm, p.x, p.omega, parameter, p.parameter);
        row.insert(row.end(), dofs.begin(), dofs.end());
        states->append(row);
        if (unknowns) {
          row.resize(leading.size());
          row.insert(row.end(), p.x.data(), p.x.data() + p.x.size());
          unknowns->append(row);
        }
        return monitor.point({index, p.omega, p.parameter, p.leg, coverage.add(p.parameter, p.leg), &p.recorded});
      },
      restart);
  add_tracking_summary(summary, c, r, o.parameter);
  summary["warnings"] = tracking_warnings(r, o, o.start.omega);
  const std::string failure = to_string(monitor.stop_reason(r.stop_reason()));
  if (!r.success()) summary["stop_reason"] = failure;
  summary["start"] = {{"omega", o.start.omega}, {o.parameter, start_value}};
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  sink.summary(summary);
  RunReport report{summary};
  if (!r.success())
    report.failure = "tracking stopped: " + failure + " after " + std::to_string(r.curve_points()) + " points (kept in " + sink.location() +
                     ")" + smoothness_hint(hbm, o.tracked);
  else
    report.brief = std::to_string(r.curve_points()) + " points, " + std::to_string(r.extrema.size()) + " extrema of " + o.parameter + ", " +
                   how_the_legs_ended(r);
  return report;
}

}  // namespace hbtrack::runs
