#include "resume_checkpoint.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "hbtrack/io/case_file.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

using nlohmann::json;

json branch_settings(json options) {
  options.erase("case");
  options["harmonic_balance"].erase("retained_dofs");  // follows from the rest; absent from older checkpoints
  options["continuation"].erase("max_points");
  options["continuation"].erase("wall_time_limit");
  return options;
}

void require_stopped_run(const std::string& dir, const std::vector<StopReason>& finished) {
  if (!std::filesystem::exists(dir + "/summary.json")) return;  // killed before its first summary: the checkpoint decides
  const std::string reason = read_summary(dir).value("stop_reason", "");
  if (std::any_of(finished.begin(), finished.end(), [&](StopReason f) { return to_string(f) == reason; }))
    throw CaseError("--resume: " + dir + " finished (" + reason + "), nothing to resume");
}

void require_same_settings(const std::string& dir, const json& saved, const json& settings) {
  if (saved != settings)
    throw CaseError("--resume: " + dir + "/checkpoint.json was computed with other settings (case, --set or options differ): " +
                    json::diff(saved, settings).dump());
}

CsvAppender open_result_csv(const std::string& path, const std::vector<std::string>& header, bool resuming, int rows) {
  if (!resuming) return CsvAppender(path, header);
  try {
    return CsvAppender::continuing(path, header, rows);
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string("--resume: ") + e.what());
  }
}

}  // namespace hbtrack::cli
