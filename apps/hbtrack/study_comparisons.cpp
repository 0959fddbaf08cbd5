#include "study_comparisons.hpp"

#include <cmath>

#include "result_folder.hpp"

namespace hbtrack::cli {

using nlohmann::json;

json compare_limit_points(const json& nominal, const json& refined, const std::string& first_output) {
  const std::string key = "max_" + first_output;
  json rows = json::array();
  for (const auto& lp : nominal) {
    if (lp.value("type", "") != "LP") continue;
    const double omega = lp.value("omega", 0.0);
    const json* best = nullptr;
    for (const auto& other : refined)
      if (other.value("type", "") == "LP" &&
          (!best || std::abs(other.value("omega", 0.0) - omega) < std::abs(best->value("omega", 0.0) - omega)))
        best = &other;
    json row = {{"omega", omega}, {key, lp.value(key, 0.0)}};
    if (best) {
      row["refined_omega"] = best->value("omega", 0.0);
      row["refined_" + key] = best->value(key, 0.0);
      row["relative_difference_omega"] = (best->value("omega", 0.0) - omega) / omega;
      row["relative_difference_" + key] = (best->value(key, 0.0) - lp.value(key, 0.0)) / std::abs(lp.value(key, 1.0));
    }
    rows.push_back(row);
  }
  return rows;
}

json compare_extrema(const json& extrema, const std::vector<TrackingCurve>& refined, const std::string& first_output) {
  json rows = json::array();
  for (const auto& e : extrema) {
    const double value = e.value("value", 0.0), omega = e.value("omega", 0.0);
    const TrackingCurve::Extremum* best = nullptr;
    double best_distance = 0;
    for (const TrackingCurve& c : refined)
      for (const auto& x : c.extrema) {
        if (x.type != e.value("type", "")) continue;
        const double d = std::hypot((x.value - value) / std::abs(value), (x.omega - omega) / omega);
        if (!best || d < best_distance) best = &x, best_distance = d;
      }
    json row = {{"type", e.value("type", "")}, {"value", value}, {"omega", omega}};
    if (best) {
      row["refined_value"] = best->value;
      row["refined_omega"] = best->omega;
      row["refined_max_" + first_output] = best->first_output;
      row["relative_difference_value"] = (best->value - value) / std::abs(value);
      row["relative_difference_omega"] = (best->omega - omega) / omega;
    }
    rows.push_back(row);
  }
  return rows;
}

std::optional<BranchPoint> stable_isola_point(const std::string& study_dir, const json& tracking, const std::string& first_output) {
  std::optional<BranchPoint> best;
  double best_output = -1e300;
  for (const auto& entry : tracking)
    for (const auto& v : entry.value("validations", json::array()))
      for (const auto& isola : v.value("isola_branches", json::array())) {
        const std::string folder = isola.value("folder", "");
        const CsvTable b = read_csv_table(study_dir + "/" + folder + "/branch.csv");
        const auto column = static_cast<size_t>(b.column("max_" + first_output));
        const auto header_end = b.header.end();
        if (std::find(b.header.begin(), header_end, "stable") == header_end) continue;
        const auto stable = static_cast<size_t>(b.column("stable"));
        for (size_t i = 0; i < b.rows.size(); ++i)
          if (b.rows[i][stable] == 1.0 && b.rows[i][column] > best_output)
            best_output = b.rows[i][column], best = BranchPoint{folder, static_cast<long>(i)};
      }
  return best;
}

json compare_with_simulation(const std::string& branch_dir, long point, const json& s, const std::vector<OutputDof>& outputs) {
  const CsvTable b = read_csv_table(branch_dir + "/branch.csv");
  const std::vector<double>& row = b.rows[static_cast<size_t>(point)];
  json cmp = {{"point", point},
              {"omega", row[0]},
              {"periods", s.value("periods", 0)},
              {"converged", s.value("converged", false)},
              {"last_change", s.value("last_change", 0.0)},
              {"wall_s", s.contains("timings") ? s["timings"].value("wall_s", 0.0) : 0.0},
              {"outputs", json::array()}};
  for (const auto& out : outputs)
    for (const char* kind : {"max_", "min_", "h1_"}) {
      const std::string key = kind + out.name;
      const double hbm = row[static_cast<size_t>(b.column(key))], sim = s.value(key, 0.0);
      cmp["outputs"].push_back({{"name", key}, {"hbm", hbm}, {"simulation", sim}, {"relative_difference", (sim - hbm) / std::abs(hbm)}});
    }
  return cmp;
}

}  // namespace hbtrack::cli
