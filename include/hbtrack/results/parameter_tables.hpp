#pragma once
// The rows and summary fields of `hbtrack continue` (continuation in a named parameter at fixed
// omega), shared by the command-line verb and the Python module. Same contract as `frc`, with
// the parameter as a column of branch.csv and a field of each special point.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "hbtrack/analysis/parameter_continuation.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack {

// branch.csv: omega, PARAM, stable (when computed), max_/min_/h1_NAME per output.
std::vector<std::string> parameter_branch_header(const CaseDefinition& c, const std::string& parameter);
std::vector<double> parameter_branch_row(const ParameterBranchPoint& p);

// summary.json "options.continue": {parameter, omega, range}.
nlohmann::json parameter_continuation_options(const std::string& parameter, double omega, double start, double end);

// What `continue` adds to summary.json: stop_reason, counts, length scale, outputs and
// special_points (type, index, omega, PARAM, located, parameters at the point, outputs).
void add_parameter_branch_summary(nlohmann::json& summary, const CaseDefinition& c, const HarmonicBalance& hbm,
                                  const ParameterBranchResult& r, int parameter);

}  // namespace hbtrack
