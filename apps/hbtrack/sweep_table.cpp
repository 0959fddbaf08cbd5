#include "sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_common.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/util/special_point_type.hpp"
#include "hbtrack/util/stop_reason.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

// What the table needs from one task's NFRC folder.
struct NfrcDigest {
  std::string status;
  long points = 0;
  std::vector<double> peaks;  // largest max_NAME per output
  double omega_at_peak = NAN;
  std::vector<std::pair<double, double>> limit_points;  // omega, max of the first output
  bool has_result = false;
};

NfrcDigest digest_nfrc(const std::string& folder, const std::vector<std::string>& outputs, Unfinished unfinished) {
  NfrcDigest d;
  if (!finished_result(folder)) {
    d.status = unfinished == Unfinished::kError ? "error" : "pending";
    return d;
  }
  const json s = read_summary(folder);
  d.status = s.value("stop_reason", "");
  d.points = s.value("points", 0L);
  const std::string first = outputs.empty() ? "" : "max_" + outputs.front();
  const json special = s.value("special_points", json::array());
  for (size_t row : limit_point_rows(special))  // lpK as track_lpK: in increasing omega
    d.limit_points.emplace_back(special[row].value("omega", NAN), first.empty() ? NAN : special[row].value(first, NAN));
  try {
    const CsvTable b = read_csv_table(folder + "/branch.csv");
    for (const std::string& name : outputs) {
      const auto column = static_cast<size_t>(b.column("max_" + name));
      double peak = NAN, omega = NAN;
      for (const auto& row : b.rows)
        if (std::isnan(peak) || row[column] > peak) peak = row[column], omega = row[0];
      d.peaks.push_back(peak);
      if (d.peaks.size() == 1) d.omega_at_peak = omega;
    }
    d.has_result = true;
  } catch (const CaseError&) {
    d.peaks.assign(outputs.size(), NAN);  // an empty or damaged branch: the row says so by its blanks
  }
  return d;
}

std::string optional_cell(double v) { return std::isnan(v) ? "" : number_text(v); }

}  // namespace

std::string task_folder(const std::string& dir, size_t index, size_t count) {
  const int width = std::max(4, static_cast<int>(std::to_string(count > 0 ? count - 1 : 0).size()));
  char name[32];
  std::snprintf(name, sizeof name, "%0*zu", width, index);
  return dir + "/tasks/" + name;
}

bool finished_result(const std::string& folder) {
  if (!std::filesystem::exists(folder + "/summary.json")) return false;
  try {
    const std::string reason = read_summary(folder).value("stop_reason", "");
    return !reason.empty() && reason != to_string(StopReason::running) && reason != to_string(StopReason::interrupted) &&
           reason != to_string(StopReason::time_limit);
  } catch (const CaseError&) {
    return false;  // half-written by a killed run
  }
}

void write_sweep_table(const std::string& dir, const SweepGrid& grid, const std::vector<std::string>& outputs,
                       const std::optional<SweepTracking>& tracking, const std::vector<Unfinished>& unfinished) {
  const size_t count = grid.tasks.size();
  std::vector<NfrcDigest> nfrcs;
  size_t most_lps = 0;
  for (size_t i = 0; i < count; ++i) {
    const std::string folder = task_folder(dir, i, count) + (tracking ? "/nfrc" : "");
    nfrcs.push_back(digest_nfrc(folder, outputs, unfinished[i]));
    most_lps = std::max(most_lps, nfrcs.back().limit_points.size());
  }
  const std::string first = outputs.empty() ? "" : outputs.front();
  std::vector<std::string> header{"task"};
  header.insert(header.end(), grid.names.begin(), grid.names.end());
  header.insert(header.end(), {"status", "points"});
  for (const std::string& name : outputs) header.push_back("peak_max_" + name);
  header.insert(header.end(), {"omega_at_peak_max_" + first, "lps"});
  for (size_t k = 1; k <= most_lps; ++k)
    header.insert(header.end(), {"lp" + std::to_string(k) + "_omega", "lp" + std::to_string(k) + "_max_" + first});
  if (tracking) {
    for (size_t k = 1; k <= most_lps; ++k)
      header.insert(header.end(), {"lp" + std::to_string(k) + "_track_stop", "lp" + std::to_string(k) + "_track_points"});
    header.insert(header.end(), {tracking->parameter + "_minima", tracking->parameter + "_maxima"});
  }

  std::ostringstream out;
  {
    for (size_t c = 0; c < header.size(); ++c) out << (c ? "," : "") << header[c];
    out << '\n';
    for (size_t i = 0; i < count; ++i) {
      const NfrcDigest& d = nfrcs[i];
      std::vector<std::string> row{std::to_string(i)};
      row.insert(row.end(), grid.tasks[i].begin(), grid.tasks[i].end());
      const bool has_summary = d.status != "pending" && d.status != "error";
      row.push_back(d.status);
      row.push_back(has_summary ? std::to_string(d.points) : "");
      for (size_t o = 0; o < outputs.size(); ++o) row.push_back(d.has_result ? optional_cell(d.peaks[o]) : "");
      row.push_back(d.has_result ? optional_cell(d.omega_at_peak) : "");
      row.push_back(has_summary ? std::to_string(d.limit_points.size()) : "");
      for (size_t k = 0; k < most_lps; ++k) {
        const bool has = k < d.limit_points.size();
        row.push_back(has ? optional_cell(d.limit_points[k].first) : "");
        row.push_back(has ? optional_cell(d.limit_points[k].second) : "");
      }
      if (tracking) {
        int minima = 0, maxima = 0;
        bool all_tracked = has_summary;
        for (size_t k = 0; k < most_lps; ++k) {
          const std::string curve = task_folder(dir, i, count) + "/track_lp" + std::to_string(k + 1);
          if (k >= d.limit_points.size()) {
            row.insert(row.end(), {"", ""});
          } else if (!finished_result(curve)) {
            row.insert(row.end(), {unfinished[i] == Unfinished::kError ? "error" : "pending", ""});
            all_tracked = false;
          } else {
            const json s = read_summary(curve);
            row.insert(row.end(), {s.value("stop_reason", ""), std::to_string(s.value("points", 0L))});
            for (const auto& sp : s.value("special_points", json::array())) {
              minima += sp.value("type", "") == to_string(CurveExtremumType::parameter_min);
              maxima += sp.value("type", "") == to_string(CurveExtremumType::parameter_max);
            }
          }
        }
        row.push_back(all_tracked ? std::to_string(minima) : "");
        row.push_back(all_tracked ? std::to_string(maxima) : "");
      }
      for (size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << row[c];
      out << '\n';
    }
  }
  write_file_atomically(dir + "/sweep.csv", out.str());
}

}  // namespace hbtrack::cli
