#include "hbtrack/runs/modes.hpp"

#include <algorithm>
#include <stdexcept>

#include "hbtrack/model/damping.hpp"

namespace hbtrack::runs {

using nlohmann::json;

RunReport modes(const CaseDefinition& c, int count, ResultSink& sink) {
  const auto t0 = RunClock::now();
  if (count < 1) throw CaseError("--count: must be >= 1");
  NormalModes modes;
  std::string failure;
  try {
    modes = normal_modes(c.model.mass, c.model.stiffness);
  } catch (const std::runtime_error& e) {
    failure = e.what();
  }
  json frequencies = json::array(), dominant = json::array();
  const Eigen::Index kept = std::min<Eigen::Index>(count, modes.frequencies.size());
  for (Eigen::Index r = 0; r < kept; ++r) {
    frequencies.push_back(modes.frequencies(r));
    Eigen::Index largest = 0;
    modes.shapes.col(r).cwiseAbs().maxCoeff(&largest);
    dominant.push_back(c.model.dof_names[static_cast<size_t>(largest)]);
  }
  if (!failure.empty()) return RunReport{json::object(), failure};
  sink.open();
  json summary = {{"verb", "modes"},           {"case", c.path},
                  {"dofs", c.model.dofs()},    {"natural_frequencies", frequencies},
                  {"dominant_dofs", dominant}, {"timings", {{"wall_s", seconds_since(t0)}}}};
  sink.summary(summary);
  return RunReport{summary, "", std::to_string(kept) + " of " + std::to_string(c.model.dofs()) + " dofs"};
}

}  // namespace hbtrack::runs
