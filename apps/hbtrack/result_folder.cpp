#include "result_folder.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hbtrack/io/json_file.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/runs/special_point_start.hpp"

namespace hbtrack::cli {

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
  return cells;
}

double parse_cell(const std::string& where, const std::string& cell) {
  // strtod, not stod: a subnormal value such as 1e-322 (a harmonic at round-off level) is a
  // number, though strtod flags its underflow.
  const char* begin = cell.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (cell.empty() || end != begin + cell.size() || !std::isfinite(value))
    throw CaseError(where + ": '" + cell + "' is not a finite number");
  return value;
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  throw CaseError(path + ":1: no column '" + name + "'");
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot read (is it a result folder of hbtrack?)");
  CsvTable t;
  t.path = path;
  std::string line;
  if (!std::getline(in, line)) throw CaseError(path + ":1: empty file, expected a header");
  t.header = split_csv(line);
  long number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    const std::string where = path + ":" + std::to_string(number);
    if (cells.size() != t.header.size())
      throw CaseError(where + ": expected " + std::to_string(t.header.size()) + " values, got " + std::to_string(cells.size()));
    std::vector<double> row;
    row.reserve(cells.size());
    for (const std::string& cell : cells) row.push_back(parse_cell(where, cell));
    t.rows.push_back(std::move(row));
  }
  return t;
}

ResultFolderContents list_result_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw CaseError(dir + ": not a result folder (no such directory)");
  // A sweep's table holds text (status, lpK_track_stop) and blanks, and its results are in the
  // task folders: read as numbers it failed on its first status cell, naming no reason.
  if (fs::exists(dir + "/sweep.json"))
    throw CaseError(dir +
                    "/sweep.csv: a sweep's table, with text columns (status) and blanks, which export does not write; export a "
                    "task's folder (" +
                    dir + "/tasks/NNNN) or read sweep.csv as CSV");
  ResultFolderContents contents{read_summary(dir), {}};
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".csv") contents.tables.push_back(entry.path().string());
  std::sort(contents.tables.begin(), contents.tables.end());
  return contents;
}

nlohmann::json read_summary(const std::string& dir) {
  const std::string path = dir + "/summary.json";
  if (!std::ifstream(path)) throw CaseError(path + ": cannot read (is " + dir + " a result folder of hbtrack?)");
  nlohmann::json summary = read_json_file(path, "a result summary");
  // Every verb writes an object; an array or a number was exported as if it were a result
  // (exit 0), and its readers index it by key.
  if (!summary.is_object())
    throw CaseError(path + ": not a result summary of hbtrack (a JSON object expected, found " + std::string(summary.type_name()) + ")");
  return summary;
}

namespace {
// A state table of `path` whose row `point` exists.
CsvTable read_state_table(const std::string& path, long point) {
  CsvTable t = read_csv_table(path);
  if (t.header.size() < 2 || t.header[0] != "omega") throw CaseError(path + ":1: expected the header omega, then the dofs' harmonics");
  if (point < 0 || point >= static_cast<long>(t.rows.size()))
    throw CaseError("--point: " + std::to_string(point) + " is beyond the last point of " + path + " (" + std::to_string(t.rows.size()) +
                    " points, from 0)");
  return t;
}
}  // namespace

HbmState read_hbm_state(const std::string& path, long point, const HarmonicBalance& hbm) {
  const CsvTable t = read_state_table(path, point);
  return {t.rows[static_cast<size_t>(point)][0], read_unknowns(t, static_cast<size_t>(point), 1, hbm)};
}

double read_state_omega(const std::string& path, long point) { return read_state_table(path, point).rows[static_cast<size_t>(point)][0]; }

Eigen::VectorXd read_unknowns(const CsvTable& table, size_t row, size_t first, const HarmonicBalance& hbm) {
  const std::vector<std::string> columns(table.header.begin() + static_cast<long>(first), table.header.end());
  const std::vector<double>& cells = table.rows[row];
  const std::vector<double> values(cells.begin() + static_cast<long>(std::min(first, cells.size())), cells.end());
  try {
    return unknowns_from_state(hbm, columns, values);
  } catch (const std::invalid_argument& e) {
    throw CaseError(table.path + ":1: " + e.what());
  }
}

std::vector<size_t> limit_point_rows(const nlohmann::json& special_points) {
  return runs::special_point_rows(special_points, SpecialPointType::limit_point);
}

std::vector<std::string> hbm_overrides(const std::string& dir, const CaseDefinition& plain) {
  const std::string path = dir + "/summary.json";
  const nlohmann::json summary = read_summary(dir);
  const nlohmann::json* options = summary.contains("options") ? &summary["options"] : nullptr;
  if (!options || !options->contains("parameters") || !options->contains("harmonic_balance"))
    throw CaseError(path + ": options.parameters or options.harmonic_balance missing");
  std::vector<std::string> overrides;
  char value[40];
  for (const auto& [name, v] : (*options)["parameters"].items()) {
    if (!v.is_number()) throw CaseError(path + ": options.parameters." + name + ": expected a number");
    if (name != "amplitude" && plain.parameters.find(name) < 0)
      throw CaseError(path + ": parameter '" + name + "' is not in " + plain.path + " (results of another case?)");
    std::snprintf(value, sizeof value, "%.17g", v.get<double>());
    overrides.push_back(name + "=" + value);
  }
  const nlohmann::json& hb = (*options)["harmonic_balance"];
  try {
    overrides.push_back("harmonic_balance.harmonics=" + hb.at("harmonics").dump());  // H, or a list [1, 3, 5]
    if (hb.contains("subharmonic")) overrides.push_back("harmonic_balance.subharmonic=" + std::to_string(hb.at("subharmonic").get<int>()));
    overrides.push_back("harmonic_balance.samples=" + std::to_string(hb.at("samples").get<int>()));
    overrides.push_back("harmonic_balance.condensation=" + hb.at("condensation").get<std::string>());
  } catch (const std::exception&) {
    throw CaseError(path + ": options.harmonic_balance needs harmonics, samples and condensation");
  }
  return overrides;
}

long parse_integer(const std::string& flag, const std::string& text, long min, long max) {
  size_t used = 0;
  long value = 0;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < min)
    throw CaseError(flag + ": must be an integer >= " + std::to_string(min) + ", got '" + text + "'");
  if (value > max) throw CaseError(flag + ": must be at most " + std::to_string(max) + ", got '" + text + "'");
  return value;
}

double parse_number(const std::string& flag, const std::string& text) {
  // strtod, not stod: stod refuses a subnormal (1e-310) as out of range.
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || std::isspace(static_cast<unsigned char>(text[0])) || !std::isfinite(value))
    throw CaseError(flag + ": must be a finite number, got '" + text + "'");
  return value;
}

double parse_positive(const std::string& flag, const std::string& text) {
  const std::string rule = flag + ": must be a number > 0, got '" + text + "'";
  double value = 0;
  try {
    value = parse_number(flag, text);
  } catch (const CaseError&) {
    throw CaseError(rule);
  }
  if (!(value > 0)) throw CaseError(rule);
  return value;
}

}  // namespace hbtrack::cli
