#include "study_branches.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include "cli_common.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

using nlohmann::json;

namespace {

// The first and last omega and the extremes of one column of DIR/branch.csv, when it has rows.
json column_range(const std::string& dir, const std::string& column) {
  if (!std::filesystem::exists(dir + "/branch.csv")) return nullptr;
  const CsvTable t = read_csv_table(dir + "/branch.csv");
  if (t.rows.empty()) return nullptr;
  const auto c = static_cast<size_t>(t.column(column));
  double lo = t.rows.front()[c], hi = lo;
  for (const auto& row : t.rows) lo = std::min(lo, row[c]), hi = std::max(hi, row[c]);
  return {lo, hi};
}

// Distance from p to the segment [a, b] (same dimension).
double segment_distance(const std::vector<double>& p, const std::vector<double>& a, const std::vector<double>& b) {
  double ab2 = 0, t = 0;
  for (size_t i = 0; i < p.size(); ++i) ab2 += (b[i] - a[i]) * (b[i] - a[i]), t += (p[i] - a[i]) * (b[i] - a[i]);
  t = ab2 > 0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double q = a[i] + t * (b[i] - a[i]) - p[i];
    d2 += q * q;
  }
  return std::sqrt(d2);
}

}  // namespace

std::vector<BranchStep> backbone_steps(const std::vector<StudyBackbone>& backbones, const std::string& case_path) {
  std::vector<BranchStep> steps;
  for (const StudyBackbone& b : backbones)
    steps.push_back({"backbone_mode" + std::to_string(b.mode),
                     {"backbone", case_path, "--mode", std::to_string(b.mode), "--range", number_text(b.min) + ":" + number_text(b.max)}});
  return steps;
}

bool switchable(const json& special_point) {
  return runs::special_point_is(special_point, SpecialPointType::branch_point) ||
         runs::special_point_is(special_point, SpecialPointType::period_doubling);
}

BranchStep switch_step(const std::string& case_path, const std::string& nfrc_dir, const json& special_point, int point) {
  std::string type = special_point.value("type", "");
  std::transform(type.begin(), type.end(), type.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return {"switch_" + type + std::to_string(point), {"switch", case_path, "--from", nfrc_dir, "--point", std::to_string(point)}};
}

std::string switched_branch_through(const std::string& study_dir, const std::vector<std::string>& switched_folders,
                                    const json& special_point, const std::vector<OutputDof>& outputs, double omega_relative,
                                    double output_relative) {
  // Coordinates scaled so that the tolerance is 1 in each: omega by the point's, every output's
  // max by its largest along the nominal NFRC (a max near zero is no scale).
  const CsvTable nfrc = read_csv_table(study_dir + "/nfrc/branch.csv");
  const double omega = special_point.value("omega", 0.0);
  std::vector<double> scale{omega_relative * std::abs(omega)};
  for (const OutputDof& o : outputs) {
    const auto c = static_cast<size_t>(nfrc.column("max_" + o.name));
    double largest = std::numeric_limits<double>::min();
    for (const auto& row : nfrc.rows) largest = std::max(largest, std::abs(row[c]));
    scale.push_back(output_relative * largest);
  }
  std::vector<double> p{omega / scale[0]};
  for (size_t i = 0; i < outputs.size(); ++i) p.push_back(special_point.value("max_" + outputs[i].name, 0.0) / scale[i + 1]);
  for (const std::string& folder : switched_folders) {
    const std::string dir = study_dir + "/" + folder;
    if (!std::filesystem::exists(dir + "/branch.csv")) continue;
    const CsvTable t = read_csv_table(dir + "/branch.csv");
    std::vector<size_t> columns{static_cast<size_t>(t.column("omega"))};
    for (const OutputDof& o : outputs) columns.push_back(static_cast<size_t>(t.column("max_" + o.name)));
    std::vector<double> previous;
    for (const auto& row : t.rows) {
      std::vector<double> q;
      for (size_t i = 0; i < columns.size(); ++i) q.push_back(row[columns[i]] / scale[i]);
      if (segment_distance(p, previous.empty() ? q : previous, q) <= 1.0) return folder;
      previous = q;
    }
  }
  return "";
}

json backbone_entry(const std::string& study_dir, const BranchStep& step, const StudyBackbone& backbone) {
  const std::string dir = study_dir + "/" + step.folder;
  const json s = read_summary(dir);
  return {{"mode", backbone.mode},
          {"range", {backbone.min, backbone.max}},
          {"folder", step.folder},
          {"points", s.value("points", 0)},
          {"stop_reason", s.value("stop_reason", "")},
          {"linear_omega", s.contains("linear_mode") ? s["linear_mode"].value("omega", 0.0) : 0.0},
          {"omega_range", column_range(dir, "omega")},
          {"damping_ratio_range", column_range(dir, "damping_ratio")},
          {"wall_s", s.contains("timings") ? s["timings"].value("wall_s", 0.0) : 0.0}};
}

json switch_entry(const std::string& study_dir, const std::string& folder, const json& special_point, int point) {
  const std::string dir = study_dir + "/" + folder;
  const json s = read_summary(dir);
  return {{"point", point},
          {"type", special_point.value("type", "")},
          {"omega", special_point.value("omega", 0.0)},
          {"folder", folder},
          {"points", s.value("points", 0)},
          {"special_points", s.value("special_points", json::array()).size()},
          {"stop_reason", s.value("stop_reason", "")},
          {"omega_range", column_range(dir, "omega")},
          {"wall_s", s.contains("timings") ? s["timings"].value("wall_s", 0.0) : 0.0}};
}

}  // namespace hbtrack::cli
