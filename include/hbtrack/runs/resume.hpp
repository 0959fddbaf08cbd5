#pragma once
// Resuming a stopped continuation run (frc, track: the CLI's --resume DIR): which settings decide
// the branch, and the stopped run's checkpoint once it is known unfinished and computed with the
// same settings. Problems are CaseErrors (bad input: exit 2).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"

namespace hbtrack::runs {

// A summary's options without the case path and without what only decides when to stop
// (continuation.max_points, continuation.wall_time_limit), which a resumed run may change.
nlohmann::json branch_settings(nlohmann::json options);

// The checkpoint at `path` must have been computed with this run's settings.
void require_same_settings(const std::string& path, const nlohmann::json& saved, const nlohmann::json& settings);

// The checkpoint of the stopped run the sink resumes, as `read` (read_continuation_state,
// read_tracking_state) gives it, once that run is known unfinished (none of the stop reasons
// `finished`) and of the same settings. Empty when the run stopped after its summary but before
// its first checkpoint (interrupted at its first point): the caller starts it over.
template <class Read>
auto checkpoint_to_resume(const ResultSink& sink, const std::vector<StopReason>& finished, const nlohmann::json& settings, Read read) {
  sink.require_unfinished(finished);
  const std::string path = sink.checkpoint_path();
  std::optional<decltype(read(path))> saved;
  if (!std::filesystem::exists(path)) {
    const nlohmann::json stopped = sink.stopped_summary();
    if (stopped.is_object() && stopped.contains("options") && stopped["options"].is_object()) {
      // The final summary holds the length scale computed (0 in the settings: automatic); the run
      // starts over, so it cannot mix with the stopped one.
      nlohmann::json stopped_settings = branch_settings(stopped["options"]), these = settings;
      stopped_settings["continuation"].erase("length_scale");
      these["continuation"].erase("length_scale");
      require_same_settings(sink.location() + "/summary.json", stopped_settings, these);
      return saved;
    }
  }
  try {
    saved = read(path);
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string("--resume: ") + e.what());
  }
  require_same_settings(path, saved->settings, settings);
  return saved;
}

}  // namespace hbtrack::runs
