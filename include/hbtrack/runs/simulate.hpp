#pragma once
// `simulate`: time integration of the full model to its periodic steady state, from rest or from
// a periodic solution of the harmonic balance (its orbit at t = 0, friction sliders where that
// orbit's steady state has them). Writes the table signals (the recorded periods of every
// output) and the summary (docs/time-integration.md).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "hbtrack/runs/start_point.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "hbtrack/util/choices.hpp"

namespace hbtrack::runs {

struct SimulateOptions {
  std::optional<double> omega;      // the forcing frequency; by default the start's
  std::optional<StartPoint> start;  // by default the motion starts from rest
  IntegrationMethod method = IntegrationMethod::newmark;
  int steps_per_period = 256;                        // newmark: time steps; dopri5: output samples (the step adapts)
  int element_steps = 0;                             // newmark: NewmarkOptions::element_steps (0: steps_per_period)
  SteadyStateOptions steady;                         // its harmonics are the case's
  nlohmann::json origin = nlohmann::json::object();  // fields added to options.simulation (from, point)
  std::string steps_name = "--steps-per-period";     // the caller's name of steps_per_period, in messages
};

RunReport simulate(const CaseDefinition& c, const SimulateOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
