#pragma once
// A run that starts at a special point of a frc result folder (track --lp/--ns/--pd, torus --ns):
// the case rebuilt with that folder's settings, and the point's state.
#include <string>

#include "cli_common.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

// The case rebuilt with the settings of the result folder `dir`, then the user's --set.
CaseDefinition case_as_in(const CommonOptions& o, const std::string& dir);

// The K-th point of `type` ("LP", "NS", "PD"; from 1, in increasing omega as the figures number
// them) of DIR/summary.json, and its state. `flag` names the option in errors.
HbmState starting_point(const std::string& dir, const std::string& type, const std::string& flag, long k, const HarmonicBalance& hbm);

}  // namespace hbtrack::cli
