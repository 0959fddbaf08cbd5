#pragma once
// A ResultSink that keeps everything in memory: what the Python module returns as dicts.
#include <deque>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "hbtrack/runs/result_sink.hpp"

namespace hbtrack::runs {

// A table as its CSV file would hold it: the header and the rows.
struct MemoryTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

class MemorySink final : public ResultSink {
 public:
  void open() override {}
  std::unique_ptr<TableSink> table(const std::string& name, const std::vector<std::string>& header, const TableStart& start = {}) override;
  void summary(const nlohmann::json& summary) override { summary_ = summary; }
  ResultSink& child(const std::string& name) override;
  std::string location() const override { return "the returned result"; }
  bool keeps_unknowns() const override { return true; }

  // The tables in the order the run created them, the last summary, the results inside.
  const std::deque<std::pair<std::string, MemoryTable>>& tables() const { return tables_; }
  const nlohmann::json& last_summary() const { return summary_; }
  const std::vector<std::pair<std::string, std::unique_ptr<MemorySink>>>& children() const { return children_; }

 private:
  std::deque<std::pair<std::string, MemoryTable>> tables_;  // a deque: the table sinks point into it
  nlohmann::json summary_;
  std::vector<std::pair<std::string, std::unique_ptr<MemorySink>>> children_;
};

}  // namespace hbtrack::runs
