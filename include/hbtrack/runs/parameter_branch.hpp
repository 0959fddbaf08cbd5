#pragma once
// `continue`: the periodic solution followed in a named parameter at a fixed frequency
// (docs/analyses.md). Writes the frc tables (runs/branch_tables.hpp's names) with the parameter
// as a column of branch, and the summary.
#include <string>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"

namespace hbtrack::runs {

struct ParameterBranchOptions {
  std::string parameter;      // a name of the case's parameters
  double omega = 0;           // rad/s, fixed
  double start = 0, end = 0;  // from the solution at start towards end
};

// Bad options throw CaseErrors; no solution at the start throws std::runtime_error (the summary
// then says no_convergence).
RunReport continue_in_parameter(const CaseDefinition& c, const ParameterBranchOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
