#pragma once
// The rows and summary fields of `hbtrack backbone`, shared by the verb and the Python module.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "hbtrack/analysis/backbone.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack {

// branch.csv: amplitude, omega, damping_ratio, xi, then per output max_NAME, min_NAME and the
// harmonic magnitudes h0_NAME .. hH_NAME.
std::vector<std::string> backbone_header(const CaseDefinition& c, const std::vector<int>& harmonics);
std::vector<double> backbone_row(const BackbonePoint& p);
// states.csv: omega, then the harmonics x = a psi of every dof (the layout of frc's states).
std::vector<std::string> backbone_state_header(int unknowns);
std::vector<double> backbone_state_row(const BackbonePoint& p, const Eigen::VectorXd& u, int unknowns);

nlohmann::json backbone_options_json(const BackboneOptions& o);
// stop_reason, counts, the linear mode (omega, damping ratio), outputs, special points.
void add_backbone_summary(nlohmann::json& summary, const CaseDefinition& c, HarmonicBalance& hbm, const BackboneResult& r);

}  // namespace hbtrack
