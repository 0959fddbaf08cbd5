#include "study_curves.hpp"

#include <algorithm>
#include <cmath>

#include "hbtrack/util/special_point_type.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

TrackingCurve read_tracking_curve_folder(const std::string& dir, const std::string& parameter, const std::string& first_output) {
  const CsvTable t = read_csv_table(dir + "/branch.csv");
  const int leg = t.column("leg"), omega = t.column("omega"), value = t.column(parameter);
  const int output = first_output.empty() ? -1 : t.column("max_" + first_output);
  TrackingCurve c;
  c.folder = dir;
  c.parameter = parameter;
  for (const auto& row : t.rows) {
    c.leg.push_back(static_cast<int>(row[static_cast<size_t>(leg)]));
    c.omega.push_back(row[static_cast<size_t>(omega)]);
    c.value.push_back(row[static_cast<size_t>(value)]);
    c.first_output.push_back(output < 0 ? 0.0 : row[static_cast<size_t>(output)]);
  }
  const nlohmann::json summary = read_summary(dir);
  for (const auto& sp : summary.value("special_points", nlohmann::json::array())) {
    const std::string type = sp.value("type", "");
    // The extrema of the parameter; an NS curve's resonance ends are not births or merges.
    if (type != to_string(CurveExtremumType::parameter_min) && type != to_string(CurveExtremumType::parameter_max)) continue;
    TrackingCurve::Extremum e;
    e.type = type;
    e.value = sp.value(parameter, 0.0);
    e.omega = sp.value("omega", 0.0);
    e.first_output = first_output.empty() ? 0.0 : sp.value("max_" + first_output, 0.0);
    c.extrema.push_back(e);
  }
  return c;
}

std::vector<Crossing> crossings_at(const TrackingCurve& curve, double value) {
  std::vector<Crossing> out;
  for (size_t i = 0; i + 1 < curve.omega.size(); ++i) {
    const double a = curve.value[i], b = curve.value[i + 1];
    // Inside the segment or at its end (the start of the curve lies exactly on its value).
    if (curve.leg[i] != curve.leg[i + 1] || a == b) continue;
    if (!((a - value) * (b - value) < 0 || b == value || (i == 0 && a == value))) continue;
    const double f = (value - a) / (b - a);
    out.push_back({curve.omega[i] + f * (curve.omega[i + 1] - curve.omega[i]),
                   curve.first_output[i] + f * (curve.first_output[i + 1] - curve.first_output[i])});
  }
  return out;
}

bool lies_on_a_curve(const std::vector<TrackingCurve>& curves, double value, double omega, double output, double relative) {
  for (const TrackingCurve& c : curves)
    for (const Crossing& x : crossings_at(c, value))
      if (std::abs(x.omega - omega) <= relative * std::abs(omega) &&
          std::abs(x.first_output - output) <= relative * std::max(std::abs(output), 1e-300))
        return true;
  return false;
}

std::vector<double> probe_values(const std::vector<TrackingCurve>& curves, double min, double max, double offset) {
  const double delta = offset * (max - min);
  std::vector<double> values;
  for (const TrackingCurve& c : curves)
    for (const auto& e : c.extrema)
      for (const double v : {e.value - delta, e.value + delta})
        if (v > min && v < max) values.push_back(v);
  if (values.empty()) values = {min + delta, max - delta};
  std::sort(values.begin(), values.end());
  std::vector<double> merged;
  for (const double v : values)
    if (merged.empty() || v - merged.back() > 0.5 * delta) merged.push_back(v);
  return merged;
}

}  // namespace hbtrack::cli
