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
  // Named first: a diff of two hashes says less than what they stand for.
  const json saved_model = saved.value("model_fnv1a", json("(none: written before model hashes)"));
  if (settings.contains("model_fnv1a") && saved_model != settings["model_fnv1a"])
    throw CaseError("--resume: " + path +
                    " was computed with another model (mass, damping, stiffness, forcing or elements differ: model_fnv1a " +
                    saved_model.dump() + " there, " + settings["model_fnv1a"].dump() + " now)");
  if (saved != settings)
    throw CaseError("--resume: " + path +
                    " was computed with other settings (case, --set or options differ): " + json::diff(saved, settings).dump());
}

json ResultSink::stopped_summary() const { return nullptr; }

}  // namespace hbtrack::runs
