#include "hbtrack/runs/fold_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hbtrack::runs {

using nlohmann::json;

double orbit_departure(const json& s) {
  double worst = 0;
  if (!s.contains("start") || !s["start"].is_object()) return worst;
  for (const auto& [key, hbm] : s["start"].items()) {
    if (key.rfind("h1_", 0) != 0 || !hbm.is_number() || !s.contains(key) || !s[key].is_number()) continue;
    const double reference = std::abs(hbm.get<double>());
    if (reference > 0) worst = std::max(worst, std::abs(s[key].get<double>() - hbm.get<double>()) / reference);
  }
  return worst;
}

namespace {

// The rows along one side (direction +1 or -1 from lp_row) for each distance, while stable.
std::vector<FoldSearchCandidate> rows_along(const std::vector<FoldSearchRow>& rows, long lp_row, int direction, double lp_omega,
                                            const std::vector<double>& distances) {
  std::vector<FoldSearchCandidate> picked;
  size_t next = 0;  // the next distance to reach
  for (long r = lp_row + direction; r >= 0 && r < static_cast<long>(rows.size()) && next < distances.size(); r += direction) {
    const FoldSearchRow& row = rows[static_cast<size_t>(r)];
    if (!row.stable) break;
    const double distance = std::abs(row.omega - lp_omega) / std::abs(lp_omega);
    if (distance < distances[next]) continue;
    picked.push_back({r, row.omega, distance});
    while (next < distances.size() && distances[next] <= distance) ++next;
  }
  return picked;
}

bool side_is_stable(const std::vector<FoldSearchRow>& rows, long row) {
  return row >= 0 && row < static_cast<long>(rows.size()) && rows[static_cast<size_t>(row)].stable;
}

}  // namespace

std::vector<FoldSearchCandidate> fold_search_rows(const std::vector<FoldSearchRow>& rows, long lp_row, double lp_omega,
                                                  const std::vector<double>& distances, const std::string& source) {
  const bool before = side_is_stable(rows, lp_row - 1), after = side_is_stable(rows, lp_row + 1);
  if (!before && !after)
    throw CaseError(source + ": neither side of the limit point (row " + std::to_string(lp_row) +
                    ") is stable: a time integration cannot start on a stable orbit next to it");
  int direction = after ? 1 : -1;
  if (before && after && rows[static_cast<size_t>(lp_row - 1)].amplitude > rows[static_cast<size_t>(lp_row + 1)].amplitude) direction = -1;
  return rows_along(rows, lp_row, direction, lp_omega, distances);
}

RunReport simulate_near_fold(const CaseDefinition& c, const FoldSearchOptions& o, ResultSink& sink, RunMonitor& monitor) {
  const auto t0 = RunClock::now();
  json summary = {{"verb", "simulate"},
                  {"stop_reason", to_string(StopReason::running)},
                  {"fold_search",
                   {{"lp", o.lp},
                    {"lp_omega", o.lp_omega},
                    {"left_the_orbit_above", kLeftTheOrbit},
                    {"candidates", o.candidates.size()},
                    {"runs", json::array()}}}};
  summary["options"] = {{"simulation", o.origin}};
  sink.open();
  sink.summary(summary);
  json& search = summary["fold_search"];
  StopReason reason = StopReason::completed;
  for (const FoldSearchCandidate& candidate : o.candidates) {
    SimulateOptions run = o.simulate;
    run.start = o.start_at(candidate.row);
    run.origin = o.origin;
    run.origin["point"] = candidate.row;
    const std::string folder = "point_" + std::to_string(candidate.row);
    const RunReport r = simulate(c, run, sink.child(folder), monitor);
    const double departure = orbit_departure(r.summary);
    const std::string stopped = r.summary.value("stop_reason", "");
    const bool held = departure <= kLeftTheOrbit;
    search["runs"].push_back({{"folder", folder},
                              {"point", candidate.row},
                              {"omega", candidate.omega},
                              {"distance", candidate.distance},
                              {"periods", r.summary.value("periods", 0)},
                              {"converged", r.summary.value("converged", false)},
                              {"last_change", r.summary.value("last_change", 0.0)},
                              {"departure", departure},
                              {"held", held}});
    sink.summary(summary);
    if (stopped != to_string(StopReason::converged) && stopped != to_string(StopReason::max_periods)) {
      reason = StopReason::interrupted;  // stopped by the monitor (Ctrl-C, time limit) or failed
      if (stopped != to_string(StopReason::interrupted) && stopped != to_string(StopReason::time_limit))
        reason = StopReason::integration_failure;
      break;
    }
    if (held) {
      search["held"] = search["runs"].back();
      break;
    }
    search["left"] = search["runs"].back();  // the closest-to-held start that left, so far
  }
  summary["stop_reason"] = to_string(reason);
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  sink.summary(summary);
  RunReport report{summary};
  char line[240];
  if (search.contains("held")) {
    const json& h = search["held"];
    std::snprintf(line, sizeof line, "the orbit held from row %ld (omega %.6g, %.2f %% from LP%d at %.6g)", h.value("point", 0L),
                  h.value("omega", 0.0), 100 * h.value("distance", 0.0), o.lp, o.lp_omega);
    report.brief = line;
    if (search.contains("left")) {
      std::snprintf(line, sizeof line, ", left it from row %ld (%.2f %%)", search["left"].value("point", 0L),
                    100 * search["left"].value("distance", 0.0));
      report.brief += line;
    }
  } else if (reason == StopReason::completed) {
    report.failure = "simulate --near-lp: no start of the " + std::to_string(search["runs"].size()) + " held the orbit (kept in " +
                     sink.location() + ")";
  } else {
    report.failure = "simulate --near-lp stopped: " + to_string(reason) + " (kept in " + sink.location() + ")";
  }
  return report;
}

}  // namespace hbtrack::runs
