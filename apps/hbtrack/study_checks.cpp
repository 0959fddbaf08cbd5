#include "study_checks.hpp"

#include <cmath>
#include <set>
#include <string>

#include "hbtrack/runs/fold_search.hpp"  // kLeftTheOrbit
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack::cli {

using nlohmann::json;

namespace {
// Left through the start of its range, then computed again over a range widened beyond the
// start, that run reaching the end: every limit point of the branch was compared.
bool continued_beyond_the_range(const json& validation) {
  const json beyond = validation.value("beyond", json::object());
  return validation.value("stop_reason", "") == to_string(StopReason::left_range) &&
         beyond.value("stop_reason", "") == to_string(StopReason::reached_end);
}

// "FOLDER: the time integration left the HBM orbit (...)", or "" when it stays on it.
std::string left_the_orbit(const std::string& folder, const json& comparison) {
  for (const auto& o : comparison.value("outputs", json::array())) {
    const std::string name = o.value("name", "");
    const double d = o.value("relative_difference", 0.0);
    if (name.rfind("h1_", 0) == 0 && std::abs(d) > runs::kLeftTheOrbit)
      return folder + ": the time integration left the HBM orbit (" + name + " " + std::to_string(static_cast<int>(std::lround(100 * d))) +
             " % off after " + std::to_string(comparison.value("periods", 0)) + " periods)";
  }
  return "";
}
}  // namespace

json failed_checks(const json& s) {
  json failed = json::array();
  std::set<std::string> continued;  // validation folders whose early stop (exit 1) was made up for
  for (const auto& t : s.value("tracking", json::array()))
    for (const auto& v : t.value("validations", json::array()))
      if (continued_beyond_the_range(v)) continued.insert(v.value("folder", ""));
  for (const auto& step : s.value("steps", json::array())) {
    const int code = step.value("exit_code", 0);
    const std::string folder = step.value("folder", "");
    // A time integration that ran is judged by whether it held the orbit (below), not by its exit
    // code: 1 also when it has not settled in the budget, which at zeta = 1e-3 a start carrying
    // the HBM's truncation error as a transient may need a thousand periods to.
    const bool simulation_ran =
        code == 1 && ((folder == "simulate" && s.contains("simulation")) || (folder == "simulate_isola" && s.contains("isola_simulation")));
    // A step its verb refused (a torus on a hysteretic law) was skipped, with its reason: no check.
    const bool skipped = code == 2 && step.contains("skipped");
    if (code != 0 && !simulation_ran && !skipped && !(code == 1 && continued.count(folder)))
      failed.push_back(folder + ": exit " + std::to_string(code) + " (see " + folder + "/log.txt)");
  }
  if (s.contains("simulation"))
    if (const std::string why = left_the_orbit("simulate", s["simulation"]); !why.empty()) failed.push_back(why);
  if (s.contains("isola_simulation"))
    if (const std::string why = left_the_orbit("simulate_isola", s["isola_simulation"]); !why.empty()) failed.push_back(why);
  // The nominal NFRC must cover its range: stopped early (max_points, say) it may not have
  // reached every limit point, and the study would track and validate only some of them.
  if (s.contains("nfrc")) {
    const std::string reason = s["nfrc"].value("stop_reason", to_string(StopReason::reached_end));
    if (reason != to_string(StopReason::reached_end))
      failed.push_back("nfrc: the nominal NFRC stopped before the end of its range (" + reason +
                       "), so the study may miss limit points and what they lead to");
  }
  for (const auto& t : s.value("tracking", json::array()))
    for (const auto& v : t.value("validations", json::array())) {
      const std::string folder = v.value("folder", "");
      const std::string reason = v.value("stop_reason", "");
      const json beyond = v.value("beyond", json::object());
      if (reason != to_string(StopReason::reached_end) && !continued_beyond_the_range(v))
        failed.push_back(
            folder + ": the validation NFRC did not reach the end of its range (" + (reason.empty() ? "no result" : reason) +
            (beyond.contains("stop_reason") ? ", and its continuation beyond the range " + beyond.value("stop_reason", "") : "") +
            "), so its limit points cannot all be compared");
      const int off = v.value("lps_off_the_curves", 0);
      if (off > 0)
        failed.push_back(folder + ": " + std::to_string(off) + " of its " + std::to_string(v.value("limit_points", json::array()).size()) +
                         " limit points lie on no tracking curve (relative distance > 1e-5)");
    }
  return failed;
}

}  // namespace hbtrack::cli
