#include "hbtrack/runs/memory_sink.hpp"

namespace hbtrack::runs {

namespace {

class MemoryTableSink final : public TableSink {
 public:
  explicit MemoryTableSink(MemoryTable& table) : table_(table) {}
  void append(const std::vector<double>& row) override { table_.rows.push_back(row); }

 private:
  MemoryTable& table_;
};

}  // namespace

std::unique_ptr<TableSink> MemorySink::table(const std::string& name, const std::vector<std::string>& header, const TableStart& /*start*/) {
  tables_.emplace_back(name, MemoryTable{header, {}});
  return std::make_unique<MemoryTableSink>(tables_.back().second);
}

ResultSink& MemorySink::child(const std::string& name) {
  children_.emplace_back(name, std::make_unique<MemorySink>());
  return *children_.back().second;
}

}  // namespace hbtrack::runs
