#pragma once
// The friction loop gain of a case's contacts (analysis/friction_loop_gain.hpp) as the runs
// report it: summary.json's "friction_loop_gain" and one warning per self-energising contact.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/analysis/friction_loop_gain.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::runs {

// At the case's parameter values, the sliding sense read over [omega_a, omega_b].
std::vector<FrictionLoopGain> case_friction_loop_gains(const CaseDefinition& c, double omega_a, double omega_b);

// One entry per element: {element, type, node (when the two dofs share one, "n4" of n4_r and
// n4_t), normal_dof, tangential_dof, sense, sense_from, mu, contact_stiffness, flexibility_nn,
// flexibility_nt, ratio, gain, self_energising, critical_stiffness, note}; null where undefined.
nlohmann::json friction_loop_gain_json(const std::vector<FrictionLoopGain>& gains);

// "elements[3] (tip_contact n4_r, n4_t): friction loop gain 1.45 > 1 ...", one per contact whose
// gain exceeds 1.
std::vector<std::string> friction_loop_gain_warnings(const std::vector<FrictionLoopGain>& gains);

}  // namespace hbtrack::runs
