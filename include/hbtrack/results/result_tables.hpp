#pragma once
// The rows and summary fields of a result folder (the contract in README "Using it"), shared by
// the command-line verbs and the Python module so that both report the same numbers.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "hbtrack/util/choices.hpp"

namespace hbtrack {

// summary.json "options": the case's parameters, harmonic balance, continuation and stability.
nlohmann::json options_json(const CaseDefinition& c, const HarmonicBalance& hbm);
// summary.json "outputs": [{name, dof}] per recorded output dof.
nlohmann::json outputs_json(const CaseDefinition& c);
// The continuation's stop reason and counters (points, Newton iterations, failed steps, ...)
// into `summary`, as every branch-writing verb reports them.
void add_continuation_counts(nlohmann::json& summary, const ContinuationSummary& s);
// Adds max_NAME, min_NAME, h1_NAME of a recorded point to a JSON object.
void add_outputs(nlohmann::json& j, const CaseDefinition& c, const RecordedPoint& p);

// branch.csv of an NFRC: omega, stable (when computed), max_/min_/h1_NAME per output; then, per
// output, h0_NAME (the mean), h2_NAME .. hH_NAME and phase1_NAME .. phaseH_NAME (docs/outputs.md).
std::vector<std::string> branch_header(const CaseDefinition& c);
std::vector<double> branch_row(const RecordedPoint& p);
// stability.csv: one row per Floquet exponent of each point (point = row of branch.csv), the
// exponents in decreasing real part, so k = 0 is the one that decides `stable`; `method` the
// code of what decided the point: 0 Hill, 1 monodromy, 2 shooting (docs/outputs.md).
std::vector<std::string> stability_header();
std::vector<std::vector<double>> stability_rows(int point, const RecordedPoint& p);
// states.csv: omega, x0, x1, ...
std::vector<std::string> state_header(int unknowns);
std::vector<double> state_row(double omega, const Eigen::VectorXd& x);

// What `frc` adds to summary.json once the NFRC is done: stop_reason, counts, the length scale
// used, outputs and special_points (each with its own outputs and the options' parameters).
void add_nfrc_summary(nlohmann::json& summary, const CaseDefinition& c, HarmonicBalance& hbm, const NfrcResult& r);

// An adaptive run's (harmonic_balance.adaptive): "adaptive_harmonics" with the min, max and mean
// of H and of the unknowns q(2H+1) over the rows, the number of changes of H, and each special
// point's H ("harmonics", that of its row).
void add_adaptive_harmonics_summary(nlohmann::json& summary, const NfrcResult& r, int retained_dofs);

// branch.csv of a tracking curve: leg, omega, the parameter, (NS and PD curves) ns_frequency,
// max_/min_/h1_NAME per output, then the harmonics' columns as branch_header.
std::vector<std::string> tracking_header(const CaseDefinition& c, const std::string& parameter,
                                         TrackedPoint tracked = TrackedPoint::limit_point);
std::vector<double> tracking_row(const FoldCurvePoint& p, TrackedPoint tracked = TrackedPoint::limit_point);
// What `track` adds to summary.json: stop_reason, closed, legs, counts, special_points (extrema).
void add_tracking_summary(nlohmann::json& summary, const CaseDefinition& c, const FoldTrackingResult& r, const std::string& parameter);

// summary.json "options.simulation" of `simulate` (the integrator's own settings come on top).
nlohmann::json simulation_options_json(IntegrationMethod method, bool from_hbm, int steps_per_period, const SteadyStateOptions& steady);

// signals.csv of a simulation: time, then one column per output; its rows.
std::vector<std::string> signals_header(const CaseDefinition& c);
std::vector<std::vector<double>> signals_rows(const SteadyStateResult& r);
// What `simulate` adds to summary.json once integrated: convergence, counts, and the last
// period's max_/min_/h1_/harmonics_NAME per output.
void add_simulation_summary(nlohmann::json& summary, const CaseDefinition& c, const SteadyStateResult& r);

// Units of the tracking systems, from the case's frequency range (as the NFRC's).
FoldScales tracking_scales(HarmonicBalance& hbm, const NfrcOptions& nfrc, double parameter_span);

}  // namespace hbtrack
