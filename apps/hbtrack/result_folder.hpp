#pragma once
// Reading back what the verbs wrote: a result folder's summary.json and its CSV tables, so that
// one verb can start from another's result (simulate from a frc point, track from an LP, isolas
// from a tracking curve). Every problem is a CaseError naming the file and the rule (exit 2).
#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/util/choices.hpp"

namespace hbtrack::cli {

// A numeric CSV file: its header and rows.
struct CsvTable {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const;  // throws CaseError when absent
};
CsvTable read_csv_table(const std::string& path);

nlohmann::json read_summary(const std::string& dir);

// The rows of summary.json's special_points that are limit points, in increasing omega: LP K is
// rows[K - 1] (runs::special_point_rows, hbtrack/runs/special_point_start.hpp).
std::vector<size_t> limit_point_rows(const nlohmann::json& special_points);

// What an export writes of a result folder: its summary and its CSV tables (sorted by name).
// CaseError when `dir` is not a folder, has no readable summary.json or is a sweep's folder.
struct ResultFolderContents {
  nlohmann::json summary;
  std::vector<std::string> tables;
};
ResultFolderContents list_result_folder(const std::string& dir);

// Row `point` (0-based, as in branch.csv) of a table whose columns are omega, then the dof
// columns (hbtrack/results/state_columns.hpp) or, as written before them, the unknowns x0, x1, ...:
// the unknowns of `hbm` (x in the unknown layout as it is: the caller checks its size).
struct HbmState {
  double omega = 0;
  Eigen::VectorXd x;
};
HbmState read_hbm_state(const std::string& path, long point, const HarmonicBalance& hbm);
// Its omega alone (before the case's system is built: `frc --from` starts its range there).
double read_state_omega(const std::string& path, long point);
// The unknowns of `hbm` from the columns `first` on of row `row` of `table`, either layout.
Eigen::VectorXd read_unknowns(const CsvTable& table, size_t row, size_t first, const HarmonicBalance& hbm);

// The settings DIR/summary.json records (parameters, harmonic balance), as case overrides: the
// case then rebuilds the harmonic balance system whose unknowns the folder's states hold.
std::vector<std::string> hbm_overrides(const std::string& dir, const CaseDefinition& plain);

// Flag values that arrive as text, checked so that a bad one gives a one-line CaseError naming it.
// Integers are at most `max` (by default INT_MAX: callers store an int, and 4294967297 wrapped to 1).
long parse_integer(const std::string& flag, const std::string& text, long min, long max = std::numeric_limits<int>::max());
double parse_number(const std::string& flag, const std::string& text);
double parse_positive(const std::string& flag, const std::string& text);
// One of a choice's names (util/choices.hpp), e.g. --method.
template <NamedChoice Choice>
Choice parse_flag_choice(const std::string& flag, const std::string& text) {
  try {
    return parse_choice<Choice>(text, flag);
  } catch (const std::invalid_argument& e) {
    throw CaseError(e.what());
  }
}

}  // namespace hbtrack::cli
