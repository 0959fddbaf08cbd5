#include "hbtrack/runs/special_point_start.hpp"

#include <algorithm>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::runs {

using nlohmann::json;

namespace {

std::string type_name(const json& special_point) {
  const json* type = special_point.is_object() && special_point.contains("type") ? &special_point["type"] : nullptr;
  return type && type->is_string() ? type->get<std::string>() : "";
}

// How errors name the points of a type: "limit points", "NS points".
std::string plural_name(SpecialPointType type) {
  return type == SpecialPointType::limit_point ? "limit points" : to_string(type) + " points";
}

}  // namespace

bool special_point_is(const json& special_point, SpecialPointType type) { return type_name(special_point) == to_string(type); }

std::vector<size_t> special_point_rows(const json& special_points, SpecialPointType type) {
  std::vector<size_t> rows;
  for (size_t i = 0; i < special_points.size(); ++i)
    if (special_point_is(special_points[i], type)) rows.push_back(i);
  const auto omega = [&](size_t row) { return special_points[row].value("omega", 0.0); };
  std::stable_sort(rows.begin(), rows.end(), [&](size_t a, size_t b) { return omega(a) < omega(b); });
  return rows;
}

size_t special_point_index(const json& special_points, SpecialPointType type, long k, const SpecialPointRequest& request) {
  if (k < 1) throw CaseError(request.keyword + ": must be an integer >= 1, got " + std::to_string(k));
  const std::vector<size_t> rows = special_point_rows(special_points, type);
  // Every NFRC looks for limit points; PD and NS points only with stability on.
  if (rows.empty() && type != SpecialPointType::limit_point)
    throw CaseError(request.keyword + ": " + request.source + " has no " + plural_name(type) +
                    " (an NFRC computed with stability finds them)");
  if (static_cast<size_t>(k) > rows.size())
    throw CaseError(request.keyword + ": " + std::to_string(k) + " is beyond the " + std::to_string(rows.size()) + " " + plural_name(type) +
                    " of " + request.source);
  return rows[static_cast<size_t>(k - 1)];
}

SwitchPoint switch_point(const json& special_points, long point, size_t state_rows, const SpecialPointRequest& request) {
  if (point < 1) throw CaseError(request.keyword + ": must be an integer >= 1, got " + std::to_string(point));
  if (static_cast<size_t>(point) > special_points.size())
    throw CaseError(request.keyword + ": " + std::to_string(point) + " is beyond the " + std::to_string(special_points.size()) +
                    " special points of " + request.source);
  SwitchPoint s;
  s.special_row = static_cast<size_t>(point - 1);
  const json& sp = special_points[s.special_row];
  if (special_point_is(sp, SpecialPointType::branch_point))
    s.type = SpecialPointType::branch_point;
  else if (special_point_is(sp, SpecialPointType::period_doubling))
    s.type = SpecialPointType::period_doubling;
  else
    throw CaseError(request.keyword + ": special point " + std::to_string(point) + " of " + request.source + " is a " + type_name(sp) +
                    "; switch follows the new branch of a BP or the period-doubled branch of a PD");
  const long row = sp.value("index", -1L);
  if (row < 0 || static_cast<size_t>(row) >= state_rows)
    throw CaseError(request.keyword + ": special point " + std::to_string(point) + " of " + request.source + ": index " +
                    std::to_string(row) + " is outside the branch's states");
  s.before_row = static_cast<size_t>(std::max(row - 1, 0L));
  s.after_row = std::min(static_cast<size_t>(row) + 1, state_rows - 1);
  return s;
}

}  // namespace hbtrack::runs
