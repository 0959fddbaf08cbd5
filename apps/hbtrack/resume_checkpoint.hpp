#pragma once
// `--resume DIR` of the continuation verbs (frc, track): which settings decide the branch, and
// the checks that DIR holds a stopped run computed with them. Problems are CaseErrors (exit 2).
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack::cli {

// A summary's options without the case path and without what only decides when to stop
// (continuation.max_points, continuation.wall_time_limit), which a resumed run may change.
nlohmann::json branch_settings(nlohmann::json options);

// DIR/summary.json must not report a finished run (one of `finished` stop reasons).
void require_stopped_run(const std::string& dir, const std::vector<StopReason>& finished);

// The checkpoint's settings must equal this run's (same case, --set and verb options).
void require_same_settings(const std::string& dir, const nlohmann::json& saved, const nlohmann::json& settings);

// The checkpoint of the stopped run in DIR as `read` (read_continuation_state,
// read_tracking_state) gives it, once the run is known unfinished and of the same settings.
template <class Read>
auto checkpoint_to_resume(const std::string& dir, const std::vector<StopReason>& finished, const nlohmann::json& settings, Read read) {
  require_stopped_run(dir, finished);
  decltype(read(dir)) saved;
  try {
    saved = read(dir + "/checkpoint.json");
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string("--resume: ") + e.what());
  }
  require_same_settings(dir, saved.settings, settings);
  return saved;
}

// A result CSV of the run: new, or, when resuming, the stopped run's file cut to its first
// `rows` rows (those the checkpoint covers).
CsvAppender open_result_csv(const std::string& path, const std::vector<std::string>& header, bool resuming, int rows);

}  // namespace hbtrack::cli
