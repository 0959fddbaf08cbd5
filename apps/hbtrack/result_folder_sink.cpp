#include "result_folder_sink.hpp"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "folder_lock.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

class CsvTableSink final : public runs::TableSink {
 public:
  explicit CsvTableSink(CsvAppender csv) : csv_(std::move(csv)) {}
  void append(const std::vector<double>& row) override { csv_.append(row); }

 private:
  CsvAppender csv_;
};

}  // namespace

void ResultFolderSink::open() {
  ensure_directory(dir_);
  lock_result_folder(dir_);
}

std::unique_ptr<runs::TableSink> ResultFolderSink::table(const std::string& name, const std::vector<std::string>& header,
                                                         const runs::TableStart& start) {
  const std::string path = dir_ + "/" + name + ".csv";
  if (!start.resumed) return std::make_unique<CsvTableSink>(CsvAppender(path, header));
  // A folder that does not fit its checkpoint is bad input.
  try {
    return std::make_unique<CsvTableSink>(start.by_point ? CsvAppender::continuing_points(path, header, start.rows)
                                                         : CsvAppender::continuing(path, header, start.rows));
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string("--resume: ") + e.what());
  }
}

void ResultFolderSink::summary(const nlohmann::json& summary) { write_json_atomically(dir_ + "/summary.json", summary); }

runs::ResultSink& ResultFolderSink::child(const std::string& name) {
  children_.push_back(std::make_unique<ResultFolderSink>(dir_ + "/" + name));
  ensure_directory(children_.back()->dir_);
  return *children_.back();
}

void ResultFolderSink::require_unfinished(const std::vector<StopReason>& finished) const {
  if (!std::filesystem::exists(dir_ + "/summary.json")) return;  // killed before its first summary: the checkpoint decides
  const std::string reason = read_summary(dir_).value("stop_reason", "");
  if (std::any_of(finished.begin(), finished.end(), [&](StopReason f) { return to_string(f) == reason; }))
    throw CaseError("--resume: " + dir_ + " finished (" + reason + "), nothing to resume");
}

nlohmann::json ResultFolderSink::stopped_summary() const {
  if (!std::filesystem::exists(dir_ + "/summary.json")) return nullptr;
  return read_summary(dir_);
}

}  // namespace hbtrack::cli
