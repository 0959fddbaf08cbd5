#pragma once
// The checks `hbtrack study` makes beyond the tracking itself: the events (limit points of the
// nominal NFRC, extrema of the tracking curves) against the same recomputed with more harmonics
// and samples, and an HBM point against its time integration.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "study_curves.hpp"

namespace hbtrack::cli {

// Each limit point of `nominal` (special points of an NFRC) with the nearest one of `refined`
// (relative omega distance): both omegas, the first output's maxima and the differences.
nlohmann::json compare_limit_points(const nlohmann::json& nominal, const nlohmann::json& refined, const std::string& first_output);

// Each extremum (the study's list for one parameter) with the nearest extremum of the same type
// on the refined curves (relative distance in value and omega).
nlohmann::json compare_extrema(const nlohmann::json& extrema, const std::vector<TrackingCurve>& refined, const std::string& first_output);

// The stable point of largest first output among the isolated branches the study computed
// (folders relative to the study's): the point a time integration checks.
struct BranchPoint {
  std::string folder;
  long point = -1;
};
std::optional<BranchPoint> stable_isola_point(const std::string& study_dir, const nlohmann::json& tracking,
                                              const std::string& first_output);

// Row `point` of DIR/branch.csv against a `simulate` summary: max, min, h1 of every output.
nlohmann::json compare_with_simulation(const std::string& branch_dir, long point, const nlohmann::json& simulation,
                                       const std::vector<OutputDof>& outputs);

}  // namespace hbtrack::cli
