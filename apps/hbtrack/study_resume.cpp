#include "study_resume.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "folder_lock.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/io/input_file.hpp"
#include "hbtrack/util/fnv1a.hpp"
#include "hbtrack/util/stop_reason.hpp"
#include "result_folder.hpp"
#include "sweep_table.hpp"

namespace hbtrack::cli {

using nlohmann::json;

namespace {

std::string fnv1a(const std::string& bytes) {
  Fnv1a h;
  h.bytes(bytes);
  return h.hex();
}

// A step orphaned by a killed study may still be computing: its folder's lock is held.
void refuse_live_steps(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_directory(ec) || !fs::exists(it->path() / ".hbtrack.lock", ec)) continue;
    if (const long owner = result_folder_owner(it->path().string()); owner != 0)
      throw CaseError("--resume: " + it->path().string() + " is still being written by another process" +
                      (owner > 0 ? " (pid " + std::to_string(owner) + ")" : "") + "; wait for it to end or stop it");
  }
}

}  // namespace

json study_settings(const std::string& case_path, const std::vector<std::string>& sets, const std::vector<std::string>& only) {
  return {{"case_fnv1a", fnv1a(read_bounded_file(case_path, kMaxCaseFileBytes, "a TOML case file"))}, {"sets", sets}, {"only", only}};
}

std::map<std::string, json> steps_to_resume(const std::string& dir, const json& settings) {
  const json s = read_summary(dir);
  const std::string where = dir + "/summary.json";
  if (s.value("verb", "") != "study")
    throw CaseError("--resume: " + where + ": not a study's summary (verb '" + s.value("verb", "") + "')");
  const std::string reason = s.value("stop_reason", "");
  if (reason == to_string(StopReason::completed) || reason == to_string(StopReason::checks_failed))
    throw CaseError("--resume: " + dir + " finished (" + reason + "), nothing to resume");
  if (!s.contains("settings"))
    throw CaseError("--resume: " + where + ": no settings (a study of an older hbtrack, which cannot resume); run it again with -o");
  if (s["settings"] != settings)
    throw CaseError("--resume: " + dir +
                    " was computed with other settings (case file, --set or --only differ): " + json::diff(s["settings"], settings).dump());
  refuse_live_steps(dir);
  std::map<std::string, json> steps;
  if (s.contains("steps") && s["steps"].is_array())
    for (const json& step : s["steps"])
      if (step.is_object() && step.contains("folder") && step["folder"].is_string() && step.contains("exit_code") &&
          step["exit_code"].is_number_integer())
        steps[step["folder"].get<std::string>()] = step;
  return steps;
}

bool step_done(const std::string& dir, const Step& step, const json& recorded) {
  const int code = recorded.value("exit_code", -1);
  if (code == 2 && step.may_be_refused && recorded.contains("skipped")) return true;
  if (code != 0 && (code != 1 || step.must_succeed)) return false;
  return finished_result(dir + "/" + step.folder);
}

}  // namespace hbtrack::cli
