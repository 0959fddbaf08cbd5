#include "study_tori.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli_common.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "hbtrack/util/stop_reason.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

using nlohmann::json;

namespace {

// The NS points' numbers K (from 1, in increasing omega, as `torus --ns K`) in the order the
// branch passes them (their rows of branch.csv), each with that row.
struct NsAlongBranch {
  int k = 0;
  long row = 0;
};
std::vector<NsAlongBranch> ns_points_along_the_branch(const json& special_points) {
  const std::vector<size_t> rows = runs::special_point_rows(special_points, SpecialPointType::neimark_sacker);
  std::vector<NsAlongBranch> along;
  for (size_t k = 0; k < rows.size(); ++k) along.push_back({static_cast<int>(k + 1), special_points[rows[k]].value("index", 0L)});
  std::stable_sort(along.begin(), along.end(), [](const NsAlongBranch& a, const NsAlongBranch& b) { return a.row < b.row; });
  return along;
}

double ns_omega(const json& special_points, int k) {
  return special_points[runs::special_point_rows(special_points, SpecialPointType::neimark_sacker)[static_cast<size_t>(k - 1)]].value(
      "omega", 0.0);
}

}  // namespace

std::vector<TorusStep> torus_steps(const std::string& case_path, const std::string& nfrc_dir, const json& special_points,
                                   const StudyTorus& torus, double omega_lo, double omega_hi) {
  const std::vector<NsAlongBranch> along = ns_points_along_the_branch(special_points);
  if (along.size() < 2) return {};
  const CsvTable branch = read_csv_table(nfrc_dir + "/branch.csv");
  const auto stable = static_cast<size_t>(branch.column("stable"));
  std::vector<TorusStep> steps;
  for (size_t i = 0; i + 1 < along.size(); ++i) {
    // A special point's row is the first past its crossing: the band's rows are [row_a, row_b).
    const long first = along[i].row, end = std::min<long>(along[i + 1].row, static_cast<long>(branch.rows.size()));
    bool unstable = first >= 0 && first < end;
    for (long r = first; unstable && r < end; ++r) unstable = branch.rows[static_cast<size_t>(r)][stable] < 0.5;
    if (!unstable) continue;
    // The band's lower NS point in omega (the numbering is in omega: the smaller K).
    const int lower = std::min(along[i].k, along[i + 1].k), upper = std::max(along[i].k, along[i + 1].k);
    TorusStep s{"torus_ns" + std::to_string(lower),
                {"torus", case_path, "--from", nfrc_dir, "--ns", std::to_string(lower), "--range",
                 number_text(omega_lo) + ":" + number_text(omega_hi)},
                lower,
                upper};
    if (torus.h1 > 0) s.args.insert(s.args.end(), {"--harmonics", std::to_string(torus.h1) + "," + std::to_string(torus.h2)});
    if (torus.n1 > 0) s.args.insert(s.args.end(), {"--samples", std::to_string(torus.n1) + "," + std::to_string(torus.n2)});
    steps.push_back(s);
  }
  return steps;
}

json torus_entry(const std::string& study_dir, const TorusStep& step, const json& special_points, const std::vector<OutputDof>& outputs,
                 const json& step_record) {
  json entry = {{"ns", step.ns},
                {"omega", ns_omega(special_points, step.ns)},
                {"other_ns", step.other_ns},
                {"other_omega", ns_omega(special_points, step.other_ns)},
                {"folder", step.folder},
                {"exit_code", step_record.value("exit_code", 0)}};
  if (step_record.contains("skipped")) {
    entry["skipped"] = step_record["skipped"];
    return entry;
  }
  const std::string dir = study_dir + "/" + step.folder;
  if (!std::filesystem::exists(dir + "/summary.json")) return entry;
  const json s = read_summary(dir);
  entry.update({{"points", s.value("points", 0)},
                {"stop_reason", s.value("stop_reason", "")},
                {"wall_s", s.contains("timings") ? s["timings"].value("wall_s", 0.0) : 0.0}});
  if (s.contains("ns_point")) entry["ns_frequency"] = s["ns_point"].value("ns_frequency", 0.0);
  if (s.contains("end")) {
    entry["end"] = s["end"];
    // Closed onto the periodic branch: at the NFRC's NS point nearest its last row.
    if (s.value("stop_reason", "") == to_string(StopReason::reached_ns_point)) {
      const double last = s["end"].value("omega", 0.0);
      const size_t count = runs::special_point_rows(special_points, SpecialPointType::neimark_sacker).size();
      int nearest = 0;
      for (int k = 1; k <= static_cast<int>(count); ++k)
        if (nearest == 0 || std::abs(ns_omega(special_points, k) - last) < std::abs(ns_omega(special_points, nearest) - last)) nearest = k;
      entry["closed_at_ns"] = nearest;
      entry["closed_at_distance"] = std::abs(ns_omega(special_points, nearest) - last);
    }
  }
  if (!std::filesystem::exists(dir + "/branch.csv")) return entry;
  const CsvTable branch = read_csv_table(dir + "/branch.csv");
  if (branch.rows.empty()) return entry;
  const auto omega = static_cast<size_t>(branch.column("omega"));
  entry["omega_range"] = {branch.rows.front()[omega], branch.rows.back()[omega]};
  json envelope = json::array();
  for (const OutputDof& o : outputs) {
    const auto hi = static_cast<size_t>(branch.column("max_" + o.name)), lo = static_cast<size_t>(branch.column("min_" + o.name));
    const auto top = std::max_element(branch.rows.begin(), branch.rows.end(), [&](const auto& a, const auto& b) { return a[hi] < b[hi]; });
    double least = branch.rows.front()[lo];
    for (const auto& row : branch.rows) least = std::min(least, row[lo]);
    envelope.push_back({{"name", o.name}, {"max", (*top)[hi]}, {"omega_at_max", (*top)[omega]}, {"min", least}});
  }
  entry["envelope"] = envelope;
  return entry;
}

}  // namespace hbtrack::cli
