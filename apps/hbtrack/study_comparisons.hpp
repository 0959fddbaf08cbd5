#pragma once
// The checks `hbtrack study` makes beyond the tracking itself: the events (limit points of the
// nominal NFRC, extrema of the tracking curves) against the same recomputed with more harmonics
// and samples, and an HBM point against its time integration.
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
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

// The point a time integration checks on the isolated branches the study computed (folders
// relative to the study's): the middle in omega of the widest stable stretch (relative to its
// omega; the larger first output between equal ones), the point farthest from where the HBM's
// verdict changes. The full model's folds lie 0.6 to 2.3 % from the HBM's on rotor 67
// (docs/rotor67.md): its points 0.06 % and 0.2 % from an isola's fold left the orbit, and so did
// the middle of a stretch 0.5 % wide (reversed sense, mu = 0.1136), where the stretch of the
// largest response was chosen. `margin` is the point's distance from its stretch's nearer end,
// relative to its omega.
struct BranchPoint {
  std::string folder;
  long point = -1;
  double margin = 0;
};
std::optional<BranchPoint> stable_isola_point(const std::string& study_dir, const nlohmann::json& tracking,
                                              const std::string& first_output);

// A validation NFRC's limit points against the tracking curves' crossings located at the same
// parameter value (`isolas --locate-only`'s "crossings"): each LP must be one of them (within
// kSameLimitPoint, relative omega and first output); crossings it does not hold belong to
// branches it does not reach. Its limit_points (with their distance), lps_off_the_curves,
// largest_distance, crossings and crossings_not_on_the_nfrc.
nlohmann::json validation_against_crossings(const nlohmann::json& validation, const nlohmann::json& crossings,
                                            const std::string& first_output);

// The resonance a user checks first: the row of DIR/branch.csv of largest first harmonic of the
// first output among the stable ones at least kSimulationDetuning (relative omega) away from
// every limit point; -1 when none. At a fold itself the truncated HBM's limit point may lie a
// little beyond the full model's, and a simulation there leaves the orbit; the first harmonic,
// not the maximum, measures the resonance when a casing caps the outward excursion.
inline constexpr double kSimulationDetuning = 2e-3;
long resonance_simulation_point(const std::string& nfrc_dir, const nlohmann::json& limit_points, const std::string& first_output);

// The first limit point (in the order of `validations`, one parameter's study entries) that lies
// on no tracking curve and is not in `tried` ("folder#K"), with the result folder it is in and its
// number there (1-based, omega order: `track --lp K`).
struct OffCurveLimitPoint {
  std::string folder;
  int index = 0;
  double omega = 0;
};
std::optional<OffCurveLimitPoint> first_limit_point_off_the_curves(const std::string& study_dir, const nlohmann::json& validations,
                                                                   const std::set<std::string>& tried);

// The resonant fold: the limit point of `limit_points` (the NFRC's, with their rows in "index")
// that ends the stable stretch of DIR/branch.csv holding row `point` (the largest stable
// response), the nearer in omega of two; 1-based in omega order (`simulate --near-lp K`), 0 when
// an NS point or the range ends the stretch on both sides, or the NFRC has no stability. Not simply the LP nearest in omega: on
// rotor 67 (sense of the geometry) that is the upper fold of another stretch.
size_t fold_ending_the_stable_stretch(const std::string& nfrc_dir, long point, const nlohmann::json& limit_points);

// The limit point of `special_points` nearest `omega` (1-based, omega order), 0 when none.
size_t nearest_limit_point(const nlohmann::json& special_points, double omega);

// Row `point` of DIR/branch.csv against a `simulate` summary: max, min, h1 of every output.
nlohmann::json compare_with_simulation(const std::string& branch_dir, long point, const nlohmann::json& simulation,
                                       const std::vector<OutputDof>& outputs);

}  // namespace hbtrack::cli
