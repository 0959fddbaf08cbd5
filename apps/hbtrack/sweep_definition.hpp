#pragma once
// What `hbtrack sweep` computes: a list of tasks, each a set of values of the case's named
// parameters, from --param/--values pairs (their cartesian product, the first parameter varying
// slowest) or from a --samples table; and, with --track, the parameter in which every limit
// point of each task's NFRC is followed. Values are kept as the text handed to the task's
// `--set NAME=VALUE`, so that sweep.csv shows exactly what ran.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::cli {

struct SweepGrid {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> tasks;  // one value per name
};

// --track PARAM[:LO:HI]
struct SweepTracking {
  std::string parameter;
  double min = 0, max = 0;
};

// The most tasks one sweep runs (README, Sweeps): each is a child process and a folder, and a
// typo such as 1:2:100000000 must fail at once rather than exhaust memory or the disk.
inline constexpr std::size_t kMaxSweepTasks = 100000;

// "A,B,C" or "LO:HI:count=N" / "LO:HI:N" (N evenly spaced values, both ends included: a count,
// not a step; N = 1 gives LO).
std::vector<std::string> parse_sweep_values(const std::string& name, const std::string& spec);

// The cartesian product of --param NAME --values SPEC pairs (given in the same order).
SweepGrid cartesian_grid(const std::vector<std::string>& names, const std::vector<std::string>& specs);

// A CSV table with a header of parameter names and one task per row.
SweepGrid read_samples(const std::string& path);

// Every name must be a named parameter of the case, given once, and not also with --set.
// `source` starts the error line: "--param:" or "FILE.csv:1: column".
void check_grid_names(const SweepGrid& grid, const CaseDefinition& c, const std::vector<std::string>& sets, const std::string& source);

// PARAM or PARAM:LO:HI (without a range: the case's [study] range of PARAM); the range must hold
// PARAM's value in every task (the tracking starts there).
SweepTracking parse_tracking(const std::string& spec, const SweepGrid& grid, const CaseDefinition& c);

// The sweep's definition as saved in DIR/sweep.json: a rerun must match it to reuse DIR.
nlohmann::json sweep_definition_json(const std::string& case_path, const std::vector<std::string>& sets, const SweepGrid& grid,
                                     const std::optional<SweepTracking>& tracking);

}  // namespace hbtrack::cli
