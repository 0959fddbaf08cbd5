#pragma once
// The tables and summary of a torus branch (analysis/torus_branch.hpp), as the other verbs write
// theirs (docs/analyses.md, "The quasi-periodic response past an NS point"):
//   branch.csv: omega, omega2, size (the phase pair's cosine coefficient, 0 at the NS point),
//               then max_NAME, min_NAME per output (extremes over the torus);
//   states.csv: omega, omega2, then every dof's torus coefficients D_h0 (the mean), D_cK1_K2,
//               D_sK1_K2 per pair (K1, K2) of the basis.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/analysis/torus_branch.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack {

std::vector<std::string> torus_branch_header(const CaseDefinition& c);
std::vector<double> torus_branch_row(const TorusPoint& p);
std::vector<std::string> torus_state_header(const TorusBasis& basis, const std::vector<std::string>& dof_names);
std::vector<double> torus_state_row(const TorusPoint& p);
// summary.json's counts, NS point, phase condition and special points (LP of the torus branch in
// omega, `index` the row of branch.csv).
void add_torus_summary(nlohmann::json& summary, const CaseDefinition& c, const TorusBranchResult& r, const TorusOptions& o);

}  // namespace hbtrack
