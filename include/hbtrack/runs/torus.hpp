#pragma once
// `torus`: the quasi-periodic response born at a Neimark-Sacker point of an NFRC, continued in
// omega (analysis/torus_branch.hpp). Writes the tables branch (omega, omega2, size, the outputs'
// extremes over the torus), states (the torus coefficients of every dof), "unknowns" for a sink
// that keeps them, and the summary.
#include <nlohmann/json.hpp>
#include <string>

#include "hbtrack/analysis/torus_branch.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "hbtrack/runs/start_point.hpp"

namespace hbtrack::runs {

struct TorusRunOptions {
  StartPoint start;  // the NS point (of an NFRC of the same case and settings)
  double omega_min = 0, omega_max = 0;
  int h1 = 0, h2 = 4, n1 = 0, n2 = 0;  // 0: defaults (TorusOptions)
  double start_fraction = 0.02;
  nlohmann::json origin = nlohmann::json::object();  // added to options.torus (from, ns)
  // How the caller names the options in its messages (the CLI's flags, Python's keywords).
  std::string range_name = "--range", harmonics_name = "--harmonics", samples_name = "--samples";
};

// Bad options throw CaseErrors naming the option; a start that cannot be refined or solved
// throws std::runtime_error (a failure of the run).
RunReport torus(const CaseDefinition& c, const TorusRunOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
