#pragma once
// `switch`: the branch crossing an NFRC at one of its branch points (BP), from the null space of
// the extended Jacobian there, or the period-doubled branch born at a period doubling (PD), the
// same switch in the harmonic balance at omega / 2 (docs/analyses.md). Writes the frc tables:
// the new branch in one piece, from the end of the leg that went back through the point to the
// end of the leg that went away from it (at a PD: from this PD to the band's other one).
#include <nlohmann/json.hpp>
#include <string>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "hbtrack/runs/start_point.hpp"
#include "hbtrack/util/special_point_type.hpp"

namespace hbtrack::runs {

struct SwitchOptions {
  SpecialPointType type = SpecialPointType::branch_point;  // or period_doubling
  long point = 0;                                          // its number among the NFRC's special points (from 1), for the summary
  StartPoint at;                                           // the BP or PD itself
  StartPoint before, after;                                // its neighbours on the NFRC: the direction the NFRC goes through it
  nlohmann::json origin = nlohmann::json::object();        // fields added to options.switch (from)
};

// `period_one`: the case the NFRC was computed with (at a PD the run halves its frequency).
// No solution near the point throws std::runtime_error (the summary then says no_convergence).
RunReport switch_branch(const CaseDefinition& period_one, const SwitchOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
