#pragma once
// The result folder of a verb (-o DIR, or --resume DIR): each table a CSV file appended and
// flushed row by row (a killed run keeps what it computed), summary.json replaced atomically,
// the folder locked while the run writes it (folder_lock.hpp), and for --resume the stopped
// run's checkpoint.json and rows. Problems with a folder to resume are CaseErrors (exit 2).
#include <memory>
#include <string>
#include <vector>

#include "hbtrack/runs/result_sink.hpp"

namespace hbtrack::cli {

class ResultFolderSink final : public runs::ResultSink {
 public:
  // resume: DIR holds a stopped run that this one goes on with.
  explicit ResultFolderSink(std::string dir, bool resume = false) : dir_(std::move(dir)), resume_(resume) {}
  void open() override;
  std::unique_ptr<runs::TableSink> table(const std::string& name, const std::vector<std::string>& header,
                                         const runs::TableStart& start = {}) override;
  void summary(const nlohmann::json& summary) override;
  ResultSink& child(const std::string& name) override;
  std::string location() const override { return dir_; }
  bool resuming() const override { return resume_; }
  void require_unfinished(const std::vector<StopReason>& finished) const override;
  std::string checkpoint_path() const override { return dir_ + "/checkpoint.json"; }
  nlohmann::json stopped_summary() const override;

 private:
  std::string dir_;
  bool resume_;
  std::vector<std::unique_ptr<ResultFolderSink>> children_;
};

}  // namespace hbtrack::cli
