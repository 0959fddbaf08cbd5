#pragma once
// `track`: a limit point (or a Neimark-Sacker or period-doubling point) followed in a second parameter (the fold's tracking curve, both
// ways from the start within the range), with the curve's extrema in that parameter. Writes the tables branch (leg, omega, parameter,
// outputs), states (leg, omega, parameter, every dof's harmonics), "unknowns" (leg, omega, parameter, x0, ...) for a sink that keeps them,
// and the summary. Resumes the stopped run when the sink says so (ResultSink::resuming).
#include <nlohmann/json.hpp>
#include <string>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "hbtrack/runs/start_point.hpp"

namespace hbtrack::runs {

struct TrackOptions {
  std::string parameter;  // a name of the case's parameters
  double parameter_min = 0, parameter_max = 0;
  TrackingMethod method = TrackingMethod::bordered;
  TrackedPoint tracked = TrackedPoint::limit_point;  // or an NS or a PD point
  StartPoint start;                                  // the limit point, NS or PD point (of an NFRC of the same case and settings)
  // Fields added to the summary's options.tracking (where the start came from: folder, lp, ...).
  nlohmann::json origin = nlohmann::json::object();
  // How the caller names the range and the parameter in its messages (the CLI's flags, Python's
  // keywords).
  std::string range_name = "--range", parameter_name = "--param";
};

// Bad options (range, parameter, start) throw CaseErrors naming the option; a fold system that
// cannot be set up at the start throws std::runtime_error (a failure of the run).
RunReport track(const CaseDefinition& c, const TrackOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
