#include "sweep_definition.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_common.hpp"
#include "hbtrack/io/input_file.hpp"
#include "hbtrack/util/fnv1a.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

// 12 significant digits: LO:HI:COUNT steps print without round-off tails (0.3, not
// 0.30000000000000004), and the text is what the task gets, so sweep.csv is exact.
std::string value_text(double v) { return number_text(v, 12); }

// `count` as text: "2000000", or "more than 100000" where reading stopped at the limit.
CaseError too_many_tasks(const std::string& where, const std::string& count) {
  return CaseError(where + ": " + count + " tasks, more than the " + std::to_string(kMaxSweepTasks) +
                   " one sweep runs (split it into several sweeps)");
}

std::string more_than_the_limit() { return "more than " + std::to_string(kMaxSweepTasks); }

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

std::string trimmed(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t\r"), end = s.find_last_not_of(" \t\r");
  return begin == std::string::npos ? "" : s.substr(begin, end - begin + 1);
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

// FNV-1a of the case file: a rerun after the case changed must not reuse the old tasks.
std::string file_fingerprint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  Fnv1a hash;
  for (char ch; in.get(ch);) hash.bytes(&ch, 1);
  return hash.hex();
}

}  // namespace

std::vector<std::string> parse_sweep_values(const std::string& name, const std::string& spec) {
  const std::string flag = "--values (" + name + ")";
  if (trimmed(spec).empty()) throw CaseError(flag + ": empty list, expected A,B,... or LO:HI:count=N");
  const std::vector<std::string> range = split(spec, ':');
  std::vector<std::string> values;
  if (range.size() == 3) {
    const double lo = parse_number(flag + " LO", trimmed(range[0])), hi = parse_number(flag + " HI", trimmed(range[1]));
    // The third field is a count, not a step (Matlab's LO:STEP:HI reads otherwise): `count=N`
    // says so explicitly, a bare N means the same.
    std::string count_text = trimmed(range[2]);
    if (count_text.rfind("count=", 0) == 0)
      count_text = trimmed(count_text.substr(6));
    else if (count_text.find('=') != std::string::npos)
      throw CaseError(flag + ": the third field of LO:HI:count=N is a number of values, got '" + range[2] + "'");
    const long count = parse_integer(flag + " COUNT", count_text, 1);
    if (static_cast<unsigned long>(count) > kMaxSweepTasks) throw too_many_tasks(flag + " COUNT", std::to_string(count));
    for (long i = 0; i < count; ++i)
      values.push_back(value_text(
          i + 1 == count && count > 1 ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(std::max(count - 1, 1L))));
    return values;
  }
  if (range.size() != 1) throw CaseError(flag + ": expected A,B,... or LO:HI:count=N, got '" + spec + "'");
  for (const std::string& item : split(spec, ',')) {
    if (values.size() == kMaxSweepTasks) throw too_many_tasks(flag, more_than_the_limit());
    if (trimmed(item).empty()) throw CaseError(flag + ": empty value in the list '" + spec + "'");
    values.push_back(value_text(parse_number(flag, trimmed(item))));
  }
  return values;
}

SweepGrid cartesian_grid(const std::vector<std::string>& names, const std::vector<std::string>& specs) {
  if (names.empty()) throw CaseError("--param: give at least one --param NAME --values ... (or --samples FILE.csv)");
  if (names.size() != specs.size())
    throw CaseError("--values: one per --param, in the same order (got " + std::to_string(names.size()) + " --param and " +
                    std::to_string(specs.size()) + " --values)");
  std::vector<std::vector<std::string>> value_lists;
  double count = 1;  // a double: the product of many counts overflows no integer check
  for (size_t j = 0; j < names.size(); ++j) {
    value_lists.push_back(parse_sweep_values(names[j], specs[j]));
    count *= static_cast<double>(value_lists.back().size());
  }
  if (count > static_cast<double>(kMaxSweepTasks)) {
    char text[32];
    std::snprintf(text, sizeof text, count < 1e15 ? "%.0f" : "%.3g", count);
    throw too_many_tasks("--values", text);
  }
  SweepGrid grid{names, {{}}};
  for (size_t j = 0; j < names.size(); ++j) {
    const std::vector<std::string>& values = value_lists[j];
    std::vector<std::vector<std::string>> product;
    for (const auto& task : grid.tasks)
      for (const std::string& v : values) {
        product.push_back(task);
        product.back().push_back(v);
      }
    grid.tasks = std::move(product);
  }
  return grid;
}

SweepGrid read_samples(const std::string& path) {
  std::istringstream in(read_bounded_file(path, kMaxCaseFileBytes, "a --samples CSV table"));
  std::string line;
  if (!std::getline(in, line) || trimmed(line).empty())
    throw CaseError(path + ":1: empty, expected a header naming the parameters (e.g. mu,clearance)");
  SweepGrid grid;
  for (const std::string& cell : split(line, ',')) {
    const std::string name = trimmed(cell);
    char* end = nullptr;
    std::strtod(name.c_str(), &end);
    if (name.empty() || end == name.c_str() + name.size())
      throw CaseError(path + ":1: expected a header naming the parameters (e.g. mu,clearance), got '" + trimmed(line) + "'");
    grid.names.push_back(name);
  }
  for (long number = 2; std::getline(in, line); ++number) {
    if (trimmed(line).empty()) continue;
    const std::vector<std::string> cells = split(line, ',');
    const std::string where = path + ":" + std::to_string(number);
    if (cells.size() != grid.names.size())
      throw CaseError(where + ": expected " + std::to_string(grid.names.size()) + " values, got " + std::to_string(cells.size()));
    if (grid.tasks.size() == kMaxSweepTasks) throw too_many_tasks(path, more_than_the_limit());
    std::vector<std::string> task;
    for (const std::string& cell : cells) task.push_back(value_text(parse_number(where, trimmed(cell))));
    grid.tasks.push_back(task);
  }
  if (grid.tasks.empty()) throw CaseError(path + ": no samples after the header");
  return grid;
}

void check_grid_names(const SweepGrid& grid, const CaseDefinition& c, const std::vector<std::string>& sets, const std::string& source) {
  for (size_t j = 0; j < grid.names.size(); ++j) {
    const std::string& name = grid.names[j];
    if (c.parameters.find(name) < 0)
      throw CaseError(source + " '" + name + "' is not a named parameter of " + c.path +
                      " (its parameters: " + joined(c.parameters.names()) + ")");
    if (std::find(grid.names.begin(), grid.names.begin() + static_cast<long>(j), name) != grid.names.begin() + static_cast<long>(j))
      throw CaseError(source + " '" + name + "' is given twice");
    for (const std::string& s : sets)
      if (s.rfind(name + "=", 0) == 0) throw CaseError(source + " '" + name + "' is swept, it cannot also be given with --set");
  }
}

SweepTracking parse_tracking(const std::string& spec, const SweepGrid& grid, const CaseDefinition& c) {
  const std::vector<std::string> parts = split(spec, ':');
  if (parts.size() != 1 && parts.size() != 3) throw CaseError("--track: expected PARAM or PARAM:LO:HI, got '" + spec + "'");
  SweepTracking t{parts[0]};
  if (c.parameters.find(t.parameter) < 0)
    throw CaseError("--track: '" + t.parameter + "' is not a named parameter of " + c.path +
                    " (its parameters: " + joined(c.parameters.names()) + ")");
  if (parts.size() == 3) {
    t.min = parse_number("--track LO", parts[1]);
    t.max = parse_number("--track HI", parts[2]);
    if (!(t.min < t.max)) throw CaseError("--track: expected PARAM:LO:HI with LO < HI, got '" + spec + "'");
  } else {
    const auto study =
        std::find_if(c.study.track.begin(), c.study.track.end(), [&](const StudyTrack& s) { return s.parameter == t.parameter; });
    if (study == c.study.track.end())
      throw CaseError("--track: give PARAM:LO:HI, the case's [study] section has no range for '" + t.parameter + "'");
    t.min = study->min;
    t.max = study->max;
  }
  const auto column = std::find(grid.names.begin(), grid.names.end(), t.parameter);
  for (size_t i = 0; i < grid.tasks.size(); ++i) {
    const double v = column == grid.names.end() ? c.parameters.value(t.parameter)
                                                : std::stod(grid.tasks[i][static_cast<size_t>(column - grid.names.begin())]);
    if (!(t.min <= v && v <= t.max))
      throw CaseError("--track: the range " + value_text(t.min) + ":" + value_text(t.max) + " must contain " + t.parameter +
                      " of every task (task " + std::to_string(i) + " has " + value_text(v) + ": the tracking starts there)");
  }
  return t;
}

nlohmann::json sweep_definition_json(const std::string& case_path, const std::vector<std::string>& sets, const SweepGrid& grid,
                                     const std::optional<SweepTracking>& tracking) {
  std::error_code ignored;
  nlohmann::json d = {{"case", std::filesystem::weakly_canonical(case_path, ignored).string()},
                      {"case_fnv1a", file_fingerprint(case_path)},
                      {"set", sets},
                      {"parameters", grid.names},
                      {"tasks", grid.tasks},
                      {"track", nullptr}};
  if (tracking) d["track"] = {{"parameter", tracking->parameter}, {"range", {tracking->min, tracking->max}}};
  return d;
}

}  // namespace hbtrack::cli
