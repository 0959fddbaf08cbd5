#pragma once
// `frc`: the nonlinear frequency response curve of a case by arc-length continuation in omega,
// with stability and special points. Writes the tables branch, states (every dof's harmonics),
// stability (when computed), special_states, element_forces (on request) and the summary
// (docs/outputs.md); "unknowns" and "special_unknowns" too for a sink that keeps them.
#include <nlohmann/json.hpp>
#include <optional>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "hbtrack/runs/start_point.hpp"

namespace hbtrack::runs {

struct FrcOptions {
  // The branch through this point towards the case's omega_end; by default the curve from the
  // case's omega_start.
  std::optional<StartPoint> start;
  nlohmann::json started_from;  // summary.json "started_from" (where `start` came from), when not null
  bool element_forces = false;  // element_forces: every element's force per point
};

// Resumes the stopped run when the sink says so (ResultSink::resuming) and checkpoints after
// every point where the sink keeps checkpoints.
RunReport frc(const CaseDefinition& c, const FrcOptions& options, ResultSink& sink, RunMonitor& monitor);

// `solve`: one periodic solution at omega (branch, states and the summary with its outputs and,
// with stability on, its Floquet multipliers). Throws a CaseError for omega <= 0 or not finite.
RunReport solve(const CaseDefinition& c, double omega, ResultSink& sink);

}  // namespace hbtrack::runs
