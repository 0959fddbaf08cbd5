#include "special_point_start.hpp"

#include "hbtrack/runs/special_point_start.hpp"

namespace hbtrack::cli {

using nlohmann::json;

CaseDefinition case_as_in(const CommonOptions& o, const std::string& dir) {
  const CaseDefinition plain = load_case(o.case_path, o.sets);
  std::vector<std::string> overrides = hbm_overrides(dir, plain);
  overrides.insert(overrides.end(), o.sets.begin(), o.sets.end());  // --set wins
  return load_case(o.case_path, overrides);
}

HbmState starting_point(const std::string& dir, SpecialPointType type, const std::string& flag, long k, const HarmonicBalance& hbm) {
  const json summary = read_summary(dir);
  const std::string path = dir + "/summary.json";
  if (!summary.contains("special_points") || !summary["special_points"].is_array())
    throw CaseError(path + ": special_points missing (is --from a frc result?)");
  const size_t row = runs::special_point_index(summary["special_points"], type, k, {flag, path});
  return read_hbm_state(dir + "/special_states.csv", static_cast<long>(row), hbm);
}

}  // namespace hbtrack::cli
