#pragma once
// A run that starts at a special point of a frc result folder (track --lp/--ns/--pd, torus --ns):
// the case rebuilt with that folder's settings, and the point's state. Which point is meant is
// decided by the library (hbtrack/runs/special_point_start.hpp), as for Python.
#include <string>

#include "cli_common.hpp"
#include "hbtrack/util/special_point_type.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

// The case rebuilt with the settings of the result folder `dir`, then the user's --set.
CaseDefinition case_as_in(const CommonOptions& o, const std::string& dir);

// The K-th point of `type` (from 1, in increasing omega as the figures number them) of
// DIR/summary.json, and its state. `flag` names the option in errors.
HbmState starting_point(const std::string& dir, SpecialPointType type, const std::string& flag, long k, const HarmonicBalance& hbm);

}  // namespace hbtrack::cli
