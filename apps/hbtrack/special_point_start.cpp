#include "special_point_start.hpp"

namespace hbtrack::cli {

using nlohmann::json;

CaseDefinition case_as_in(const CommonOptions& o, const std::string& dir) {
  const CaseDefinition plain = load_case(o.case_path, o.sets);
  std::vector<std::string> overrides = hbm_overrides(dir, plain);
  overrides.insert(overrides.end(), o.sets.begin(), o.sets.end());  // --set wins
  return load_case(o.case_path, overrides);
}

HbmState starting_point(const std::string& dir, const std::string& type, const std::string& flag, long k, const HarmonicBalance& hbm) {
  const json summary = read_summary(dir);
  const std::string path = dir + "/summary.json";
  if (!summary.contains("special_points") || !summary["special_points"].is_array())
    throw CaseError(path + ": special_points missing (is --from a frc result?)");
  const std::vector<size_t> rows = special_point_rows(summary["special_points"], type);
  const std::string name = type == "LP" ? "limit points" : type + " points";
  if (rows.empty() && type != "LP")
    throw CaseError(flag + ": " + path + " has no " + name + " (an NFRC computed with stability finds them)");
  if (static_cast<size_t>(k) > rows.size())
    throw CaseError(flag + ": " + std::to_string(k) + " is beyond the " + std::to_string(rows.size()) + " " + name + " of " + path);
  return read_hbm_state(dir + "/special_states.csv", static_cast<long>(rows[static_cast<size_t>(k - 1)]), hbm);
}

}  // namespace hbtrack::cli
