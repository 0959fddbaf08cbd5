#pragma once
// `backbone`: the nonlinear mode of a linear mode by the extended periodic motion concept
// (docs/analyses.md): omega and the modal damping ratio against the modal amplitude. Every dof
// is an unknown (the negative modal damping acts on the whole model): the case's condensation is
// replaced by none. Writes the tables branch, states (every dof's harmonics of the physical
// motion), "unknowns" (a, omega, the mode's unknowns) for a sink that keeps them, and the summary.
#include "hbtrack/analysis/backbone.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"

namespace hbtrack::runs {

// options.continuation is the case's. Bad options throw CaseErrors; no solution at the start
// throws std::runtime_error (the summary then says no_convergence).
RunReport backbone(CaseDefinition c, BackboneOptions options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
