#pragma once
// `hbtrack study --resume DIR`: a stopped study (Ctrl-C, SIGTERM, a failed step, or killed
// outright, which leaves `stop_reason: running`) goes on in its own folder. Each step is a verb
// writing its own folder under DIR; a step the stopped study recorded as ended (exit 0, or 1 for
// a step allowed to fail) whose folder holds a finished summary.json, or that was skipped (exit 2
// of a step that may be refused), is not run again, its
// recorded exit code and time reused; every other step is run again from an empty folder. The
// page and summary then equal an uninterrupted run's, timings aside.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "study_plan.hpp"

namespace hbtrack::cli {

// What decides a study's steps: the case file's bytes (as an FNV-1a hash), --set and --only.
nlohmann::json study_settings(const std::string& case_path, const std::vector<std::string>& sets, const std::vector<std::string>& only);

// The steps of the stopped study in DIR, by folder, as its summary.json recorded them ended.
// Refuses (CaseError, exit 2) a DIR that is not a study, a finished study, other settings, and a
// step folder still being written by a live process (a step orphaned by a killed study).
std::map<std::string, nlohmann::json> steps_to_resume(const std::string& dir, const nlohmann::json& settings);

// True when `recorded` (an entry of steps_to_resume) ended and DIR/folder holds its finished
// result, or the step was refused and recorded as skipped (it would be refused again).
bool step_done(const std::string& dir, const Step& step, const nlohmann::json& recorded);

}  // namespace hbtrack::cli
