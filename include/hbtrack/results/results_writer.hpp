#pragma once
// Result folders (the contract in README "Using it"): a branch CSV appended and flushed point by point, so a
// killed run keeps what it computed, and summary.json replaced atomically.
#include <Eigen/Dense>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace hbtrack {

// A result file that could not be written (a full disk, a file-size limit): the system failed the
// run (exit code 3), which a run must not report as a continuation that did not converge.
class WriteFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CsvAppender {
 public:
  CsvAppender(const std::string& path, const std::vector<std::string>& header);
  // Appends to an existing file of a stopped run: checks its header, keeps its first `rows`
  // rows and drops any after them (written after the checkpoint the run resumes from).
  static CsvAppender continuing(const std::string& path, const std::vector<std::string>& header, int rows);
  // The same for a table of several rows per point whose first column is the point's index:
  // keeps the rows of points 0 .. points-1.
  static CsvAppender continuing_points(const std::string& path, const std::vector<std::string>& header, int points);
  void append(const std::vector<double>& row);
  const std::string& path() const { return path_; }

 private:
  CsvAppender(const std::string& path, size_t columns);  // opens path for appending
  // Keeps the header and the leading rows for which keep(line, rows kept so far) holds.
  template <class Keep>
  static CsvAppender keep_leading_rows(const std::string& path, const std::vector<std::string>& header, Keep keep, int expected);
  std::string path_;
  std::ofstream out_;
  size_t columns_;
};

// Writes `bytes` to PATH.tmp, checks every write, fsyncs and closes it, then renames it over
// PATH: PATH is the old file or the complete new one, never a partial one. Throws
// WriteFailed naming the file and the reason (a full disk) and removes PATH.tmp.
void write_file_atomically(const std::string& path, const std::string& bytes);

// write_file_atomically of the document, indented by 2.
void write_json_atomically(const std::string& path, const nlohmann::json& document);

// Creates DIR (and parents); throws std::runtime_error naming it on failure.
void ensure_directory(const std::string& dir);

}  // namespace hbtrack
