#pragma once
// `isolas`: the limit points where tracking curves cross param = at, and the branch in omega
// through each new one: an isolated branch ("isola", closed on itself) or the main branch
// ("open"). Writes the summary (every crossing with its status) and, per branch followed, a
// result of its own inside the sink, named isola_K or open_K, with the tables of a branch
// (runs/branch_tables.hpp).
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"

namespace hbtrack::runs {

struct IsolaOptions {
  std::string parameter;                             // the tracked parameter, a name of the case's parameters
  double at = 0;                                     // its value
  std::vector<std::vector<FoldCurvePoint>> curves;   // the tracking curves (omega, parameter, x)
  bool locate_only = false;                          // the crossings alone, no branches
  nlohmann::json origin = nlohmann::json::object();  // fields added to the summary's options.isolas
};

RunReport isolas(const CaseDefinition& c, const IsolaOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
