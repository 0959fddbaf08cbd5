#include "study_comparisons.hpp"

#include <algorithm>
#include <cmath>

#include "hbtrack/runs/special_point_start.hpp"
#include "result_folder.hpp"
#include "study_plan.hpp"

namespace hbtrack::cli {

using nlohmann::json;

json compare_limit_points(const json& nominal, const json& refined, const std::string& first_output) {
  const std::string key = "max_" + first_output;
  json rows = json::array();
  for (const auto& lp : nominal) {
    if (!runs::special_point_is(lp, SpecialPointType::limit_point)) continue;
    const double omega = lp.value("omega", 0.0);
    const json* best = nullptr;
    for (const auto& other : refined)
      if (runs::special_point_is(other, SpecialPointType::limit_point) &&
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

namespace {

// Within kSimulationDetuning (relative omega) of a limit point of `special_points`: a simulation
// started there may leave the orbit (the header says why).
bool near_a_limit_point(double omega, const json& special_points) {
  for (const auto& sp : special_points)
    if (runs::special_point_is(sp, SpecialPointType::limit_point) &&
        std::abs(omega - sp.value("omega", 0.0)) <= kSimulationDetuning * std::abs(omega))
      return true;
  return false;
}

// The row of the stable stretch (contiguous stable rows) around row i farthest in omega from both
// of the stretch's ends, where the verdict changes at a fold or an NS point.
size_t middle_of_stable_stretch(const CsvTable& b, size_t stable, size_t i) {
  size_t lo = i, hi = i;
  while (lo > 0 && b.rows[lo - 1][stable] == 1.0) --lo;
  while (hi + 1 < b.rows.size() && b.rows[hi + 1][stable] == 1.0) ++hi;
  size_t middle = i;
  double margin = -1;
  for (size_t k = lo; k <= hi; ++k) {
    const double omega = b.rows[k][0];
    const double m = std::min(std::abs(omega - b.rows[lo][0]), std::abs(omega - b.rows[hi][0]));
    if (m > margin) margin = m, middle = k;
  }
  return middle;
}

}  // namespace

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
        for (size_t lo = 0; lo < b.rows.size(); ++lo) {
          if (b.rows[lo][stable] != 1.0) continue;
          size_t hi = lo;
          double output = b.rows[lo][column];
          while (hi + 1 < b.rows.size() && b.rows[hi + 1][stable] == 1.0) output = std::max(output, b.rows[++hi][column]);
          const size_t middle = middle_of_stable_stretch(b, stable, lo);
          const double omega = b.rows[middle][0];
          const double margin = std::min(std::abs(omega - b.rows[lo][0]), std::abs(omega - b.rows[hi][0])) / std::abs(omega);
          if (!best || margin > best->margin || (margin == best->margin && output > best_output))
            best = BranchPoint{folder, static_cast<long>(middle), margin}, best_output = output;
          lo = hi;
        }
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

json validation_against_crossings(const json& validation, const json& crossings, const std::string& first_output) {
  const std::string& out = first_output;
  json lps = json::array();
  double worst = 0;
  int off_the_curves = 0;
  std::vector<bool> used(crossings.size(), false);
  for (const auto& sp : validation.value("special_points", json::array())) {
    if (!runs::special_point_is(sp, SpecialPointType::limit_point)) continue;
    const double omega = sp.value("omega", 0.0), output = out.empty() ? 0.0 : sp.value("max_" + out, 0.0);
    double best = 1e300;
    size_t best_k = crossings.size();
    for (size_t k = 0; k < crossings.size(); ++k) {
      // A crossing outside the case's omega range is located all the same (`isolas` only does
      // not follow a branch from it): a validation continued beyond the range meets it there.
      const std::string status = crossings[k].value("status", "");
      if (status != "located" && status != "duplicate" && status != "outside_range") continue;
      const double d_omega = std::abs(crossings[k].value("omega", 0.0) - omega) / std::abs(omega);
      const double d_output =
          out.empty() ? 0.0 : std::abs(crossings[k].value("max_" + out, 0.0) - output) / std::max(std::abs(output), 1e-300);
      if (std::max(d_omega, d_output) < best) best = std::max(d_omega, d_output), best_k = k;
    }
    const bool on_curve = best <= kSameLimitPoint;
    if (on_curve)
      used[best_k] = true, worst = std::max(worst, best);
    else
      ++off_the_curves;
    lps.push_back({{"omega", omega}, {"max_" + out, output}, {"distance", best}, {"on_a_tracking_curve", on_curve}});
  }
  int unseen = 0;
  for (size_t k = 0; k < crossings.size(); ++k)
    if (crossings[k].value("status", "") == "located" && !used[k]) ++unseen;
  return {{"limit_points", lps},
          {"lps_off_the_curves", off_the_curves},
          {"largest_distance", worst},
          {"crossings", crossings.size()},
          {"crossings_not_on_the_nfrc", unseen}};
}

long resonance_simulation_point(const std::string& nfrc_dir, const json& limit_points, const std::string& first_output) {
  const CsvTable b = read_csv_table(nfrc_dir + "/branch.csv");
  const auto amplitude = static_cast<size_t>(b.column("h1_" + first_output));
  const bool has_stability = std::find(b.header.begin(), b.header.end(), "stable") != b.header.end();
  const auto stable = has_stability ? static_cast<size_t>(b.column("stable")) : 0;
  long best = -1;
  for (size_t i = 0; i < b.rows.size(); ++i)
    if ((!has_stability || b.rows[i][stable] == 1.0) && !near_a_limit_point(b.rows[i][0], limit_points) &&
        (best < 0 || b.rows[i][amplitude] > b.rows[static_cast<size_t>(best)][amplitude]))
      best = static_cast<long>(i);
  return best;
}

std::optional<OffCurveLimitPoint> first_limit_point_off_the_curves(const std::string& study_dir, const json& validations,
                                                                   const std::set<std::string>& tried) {
  for (const auto& v : validations)
    for (const auto& lp : v.value("limit_points", json::array())) {
      if (lp.value("on_a_tracking_curve", true)) continue;
      const std::string folder = v.value("limit_points_folder", v.value("folder", ""));
      const json points = read_summary(study_dir + "/" + folder).value("special_points", json::array());
      const std::vector<size_t> rows = limit_point_rows(points);
      for (size_t j = 0; j < rows.size(); ++j)
        if (points[rows[j]].value("omega", 0.0) == lp.value("omega", 0.0) && !tried.count(folder + "#" + std::to_string(j + 1)))
          return OffCurveLimitPoint{folder, static_cast<int>(j + 1), lp.value("omega", 0.0)};
    }
  return std::nullopt;
}

size_t fold_ending_the_stable_stretch(const std::string& nfrc_dir, long point, const json& limit_points) {
  const CsvTable b = read_csv_table(nfrc_dir + "/branch.csv");
  if (std::find(b.header.begin(), b.header.end(), "stable") == b.header.end()) return 0;  // no sides to tell apart
  const auto stable = static_cast<size_t>(b.column("stable"));
  long lo = point, hi = point;
  const long rows = static_cast<long>(b.rows.size());
  while (lo > 0 && b.rows[static_cast<size_t>(lo - 1)][stable] == 1.0) --lo;
  while (hi + 1 < rows && b.rows[static_cast<size_t>(hi + 1)][stable] == 1.0) ++hi;
  const double omega = b.rows[static_cast<size_t>(point)][0];
  const std::vector<size_t> lps = limit_point_rows(limit_points);
  size_t fold = 0;
  double nearest = 1e300;
  for (size_t k = 0; k < lps.size(); ++k) {
    // The stepper numbers a special point by the branch point nearest it: the stretch's end
    // row or the unstable one next to it.
    const long row = limit_points[lps[k]].value("index", -1L);
    const double distance = std::abs(limit_points[lps[k]].value("omega", 0.0) - omega);
    if ((std::abs(row - lo) <= 1 || std::abs(row - hi) <= 1) && distance < nearest) nearest = distance, fold = k + 1;
  }
  return fold;
}

size_t nearest_limit_point(const json& special_points, double omega) {
  const std::vector<size_t> rows = limit_point_rows(special_points);
  size_t lp = 0;
  double best = 1e300;
  for (size_t k = 0; k < rows.size(); ++k) {
    const double distance = std::abs(special_points[rows[k]].value("omega", 0.0) - omega);
    if (distance < best) best = distance, lp = k + 1;
  }
  return lp;
}

}  // namespace hbtrack::cli
