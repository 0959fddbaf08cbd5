#pragma once
// `simulate --near-lp K`: where the full model's periodic branch ends next to a limit point of
// the harmonic balance. Time integrations start on the HBM orbit at rows of the NFRC's stable side
// of the fold, closest first (0.2 %, 0.5 %, 1 %, ... of omega away from the LP), until one holds
// the orbit: the full model's fold lies between the last row that left and the first that held
// (docs/time-integration.md). Each integration is a `simulate` result of its own (point_R/).
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_monitor.hpp"
#include "hbtrack/runs/run_report.hpp"
#include "hbtrack/runs/simulate.hpp"
#include "hbtrack/runs/start_point.hpp"

namespace hbtrack::runs {

// A time integration from an HBM point whose first harmonics end this far (relative) from the
// HBM's has left the orbit: settled orbits of rotor 67 differ from H = 10's by at most 0.5 % in
// first harmonics (2.4 % in extremes), which leaves room for a transient not yet decayed (at
// zeta = 1e-3, 69 % of it after 60 periods), while a departure (rotor 67 reversed: 67 %) is far
// beyond. The study fails a time integration that leaves (apps/hbtrack/study_checks.cpp).
inline constexpr double kLeftTheOrbit = 0.1;

// The largest relative difference between the first harmonic of an output at the end of a
// `simulate` run and on the HBM orbit it started from (summary.json's h1_X and start.h1_X).
double orbit_departure(const nlohmann::json& simulate_summary);

// One row of the NFRC: its omega, whether Hill's method found it stable, the first harmonic of
// the first output (to choose the resonant side when both sides of a fold are stable).
struct FoldSearchRow {
  double omega = 0;
  bool stable = false;
  double amplitude = 0;
};
struct FoldSearchCandidate {
  long row = 0;
  double omega = 0;
  double distance = 0;  // relative omega from the LP
};

// The rows to start from: along the side of the LP (the branch's points before or after
// lp_row, the NFRC's point nearest to it) whose first point is stable (both stable: the one of
// larger amplitude), for each distance the first row at least that far from lp_omega, while the
// stretch stays stable. A row is taken once. CaseError (naming `source`) when neither side is
// stable.
std::vector<FoldSearchCandidate> fold_search_rows(const std::vector<FoldSearchRow>& rows, long lp_row, double lp_omega,
                                                  const std::vector<double>& distances, const std::string& source);

struct FoldSearchOptions {
  SimulateOptions simulate;  // its start is set for each candidate
  int lp = 0;                // K of --near-lp, as the summary names it
  double lp_omega = 0;
  std::vector<FoldSearchCandidate> candidates;
  std::function<StartPoint(long row)> start_at;  // the HBM point of a row of the NFRC
  nlohmann::json origin = nlohmann::json::object();
};

// Integrates from each candidate in turn into child sinks point_R until one holds the orbit
// (orbit_departure <= kLeftTheOrbit). The summary's fold_search lists every run; failure when
// none held or the monitor stopped the search.
RunReport simulate_near_fold(const CaseDefinition& c, const FoldSearchOptions& options, ResultSink& sink, RunMonitor& monitor);

}  // namespace hbtrack::runs
