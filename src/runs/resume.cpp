#include "hbtrack/runs/resume.hpp"

namespace hbtrack::runs {

using nlohmann::json;

json branch_settings(json options) {
  options.erase("case");
  options["harmonic_balance"].erase("retained_dofs");  // follows from the rest; absent from older checkpoints
  options["continuation"].erase("max_points");
  options["continuation"].erase("wall_time_limit");
  return options;
}

void require_same_settings(const std::string& path, const json& saved, const json& settings) {
  if (saved != settings)
    throw CaseError("--resume: " + path +
                    " was computed with other settings (case, --set or options differ): " + json::diff(saved, settings).dump());
}

}  // namespace hbtrack::runs
