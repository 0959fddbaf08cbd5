#pragma once
// Where a run writes what it computes: named tables (branch, states, stability, ...) whose rows
// arrive point by point, the summary (written again as the run goes on: "running" first, the
// final one last) and results of its own inside (the branches isolas finds). The command-line
// tool gives a result folder (CSV files appended row by row, summary.json replaced atomically:
// apps/hbtrack/result_folder_sink.hpp), Python tables in memory (runs/memory_sink.hpp); a run
// writes the same rows and summary to either.
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack::runs {

class TableSink {
 public:
  virtual ~TableSink() = default;
  virtual void append(const std::vector<double>& row) = 0;
};

// How a table starts: empty, or, for a run that resumes a stopped one, with the stopped run's
// first `rows` rows (when `by_point`, the rows of its points 0 .. rows-1: a table whose first
// column is the point, several rows each).
struct TableStart {
  bool resumed = false;
  int rows = 0;
  bool by_point = false;
};

class ResultSink {
 public:
  virtual ~ResultSink() = default;
  // Claims the destination once the run's input is checked, before the first write (a folder is
  // created and locked): bad input leaves nothing behind.
  virtual void open() = 0;
  virtual std::unique_ptr<TableSink> table(const std::string& name, const std::vector<std::string>& header,
                                           const TableStart& start = {}) = 0;
  virtual void summary(const nlohmann::json& summary) = 0;
  // A result inside this one (a branch of isolas), opened; it lives as long as this sink.
  virtual ResultSink& child(const std::string& name) = 0;
  // Where the results are, for messages: "kept in <location>".
  virtual std::string location() const = 0;
  // True when the caller also wants the raw harmonic-balance unknowns of every point (tables
  // "unknowns" and "special_unknowns": omega, x0, x1, ...), which Python hands back as the start
  // of a later run; a result folder keeps the dofs' harmonics alone (states.csv), from which
  // read_hbm_state recovers the unknowns.
  virtual bool keeps_unknowns() const { return false; }

  // What a resumable run (frc, track) needs. resuming(): this sink goes on with the result of a
  // stopped run (the CLI's --resume DIR), whose checkpoint the run reads and whose rows it keeps.
  virtual bool resuming() const { return false; }
  // Refuses a stopped run that in fact finished: its summary's stop_reason is one of `finished`.
  virtual void require_unfinished(const std::vector<StopReason>& /*finished*/) const {}
  // The file a resumable run keeps its checkpoint in, written after every accepted point ("" for
  // none: results in memory are not resumed).
  virtual std::string checkpoint_path() const { return ""; }
  // The stopped run's last summary (null when it wrote none), for a run stopped before its first
  // checkpoint: the settings it was computed with.
  virtual nlohmann::json stopped_summary() const;
};

}  // namespace hbtrack::runs
