// The study's comparisons (apps/hbtrack/study_comparisons.cpp): which crossings a validation
// NFRC's limit points are matched with, and which isola point a time integration starts from.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "study_comparisons.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_comparisons {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json validation_with_a_limit_point(double omega, double max_le) {
  return {{"special_points", json::array({{{"type", "LP"}, {"omega", omega}, {"max_le", max_le}}})}};
}

json crossing(const std::string& status, double omega, double max_le) { return {{"status", status}, {"omega", omega}, {"max_le", max_le}}; }

}  // namespace

TEST(StudyComparisons, ALimitPointBeyondTheCaseRangeIsMatchedWithTheCrossingLocatedThere) {
  // A validation continued below omega_start meets the lower fold at 535 rad/s; `isolas` locates
  // the tracking curve's crossing there and marks it outside_range (it follows no branch from it):
  // it is on the curve all the same (the rotor 67 study counted 14 such limit points as off).
  const json v = validation_with_a_limit_point(535.0, 1.8e-4);
  using hbtrack::cli::validation_against_crossings;
  const json outside = validation_against_crossings(v, json::array({crossing("outside_range", 535.0 * (1 + 1e-9), 1.8e-4)}), "le");
  EXPECT_EQ(outside["lps_off_the_curves"], 0);
  EXPECT_TRUE(outside["limit_points"][0]["on_a_tracking_curve"].get<bool>());
  // A crossing whose Newton failed holds no limit point, nor does one further than kSameLimitPoint.
  const json failed = validation_against_crossings(v, json::array({crossing("failed", 535.0, 1.8e-4)}), "le");
  EXPECT_EQ(failed["lps_off_the_curves"], 1);
  const json far = validation_against_crossings(v, json::array({crossing("outside_range", 535.0 * (1 + 1e-3), 1.8e-4)}), "le");
  EXPECT_EQ(far["lps_off_the_curves"], 1);
}

TEST(StudyComparisons, TheIsolaPointToSimulateIsTheMiddleOfTheWidestStableStretch) {
  // Two isolas. Rows: omega, max_le, stable. The first's largest response (rows 0-1, 5.0) is on a
  // stretch 0.1 % wide; its stretch of rows 3-6 (997 to 985 rad/s) has its middle at row 5 (990:
  // 5 rad/s from 985, 7 from 997, margin 5/990). The second isola's only stretch is 0.4 % wide
  // (margin 2/1000): the first's wide stretch wins, although the second's response (6.0) and the
  // first's narrow stretch's are larger. (The former rule, the stretch of the largest response,
  // chose a stretch narrower than the full model's fold shift on rotor 67, which left the orbit.)
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_isola_point_" + std::to_string(getpid()));
  fs::create_directories(dir / "isolas_mu_1" / "isola_1");
  fs::create_directories(dir / "isolas_mu_2" / "isola_1");
  std::ofstream(dir / "isolas_mu_1" / "isola_1" / "branch.csv") << "omega,max_le,stable\n"
                                                                   "999.5,5.0,1\n"
                                                                   "1000.5,4.9,1\n"
                                                                   "995.0,4.8,0\n"
                                                                   "997.0,4.5,1\n"
                                                                   "993.0,4.3,1\n"
                                                                   "990.0,4.0,1\n"
                                                                   "985.0,3.8,1\n"
                                                                   "984.0,3.0,0\n";
  std::ofstream(dir / "isolas_mu_2" / "isola_1" / "branch.csv") << "omega,max_le,stable\n"
                                                                   "997.0,5.5,0\n"
                                                                   "998.0,6.0,1\n"
                                                                   "1000.0,6.0,1\n"
                                                                   "1002.0,6.0,1\n"
                                                                   "1003.0,5.0,0\n";
  auto isola = [](const std::string& folder) { return json{{"folder", folder}, {"special_points", json::array()}}; };
  const json tracking = json::array(
      {{{"validations", json::array({{{"isola_branches", json::array({isola("isolas_mu_1/isola_1"), isola("isolas_mu_2/isola_1")})}}})}}});
  const auto middle = hbtrack::cli::stable_isola_point(dir.string(), tracking, "le");
  ASSERT_TRUE(middle.has_value());
  EXPECT_EQ(middle->folder, "isolas_mu_1/isola_1");
  EXPECT_EQ(middle->point, 5);
  EXPECT_NEAR(middle->margin, 5.0 / 990.0, 1e-15);
  // Without the first isola, the second's stretch, at its middle (row 2, margin 2/1000).
  const json second = json::array({{{"validations", json::array({{{"isola_branches", json::array({isola("isolas_mu_2/isola_1")})}}})}}});
  const auto other = hbtrack::cli::stable_isola_point(dir.string(), second, "le");
  ASSERT_TRUE(other.has_value());
  EXPECT_EQ(other->point, 2);
  EXPECT_NEAR(other->margin, 2.0 / 1000.0, 1e-15);
  fs::remove_all(dir);
}

TEST(StudyComparisons, TheResonantFoldIsTheLimitPointThatEndsTheStretchOfTheLargestResponse) {
  // Rotor 67's shape in the geometry's sense: an upper fold (LP2, 2242, row 2) ends the stretch
  // of rows 0-1; the largest response (row 7, 2022) lies on the stretch of rows 5-8 that the
  // lower fold (LP1, 1659, row 4) starts and an NS point ends. LP2 is the nearer in omega.
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_resonant_fold_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "branch.csv") << "omega,stable\n2200,1\n2241,1\n2242,0\n1800,0\n1659.5,0\n1660,1\n1900,1\n2022,1\n2080,1\n2100,0\n";
  const json lps = json::array({{{"type", "LP"}, {"omega", 1659.3}, {"index", 4}}, {{"type", "LP"}, {"omega", 2242.1}, {"index", 2}}});
  EXPECT_EQ(hbtrack::cli::fold_ending_the_stable_stretch(dir.string(), 7, lps), 1u);  // LP1, in omega order
  EXPECT_EQ(hbtrack::cli::fold_ending_the_stable_stretch(dir.string(), 0, lps), 2u);
  // With its fold numbered by the stretch's own first row instead of the unstable one before it,
  // the same.
  const json shifted = json::array({{{"type", "LP"}, {"omega", 1659.3}, {"index", 5}}, {{"type", "LP"}, {"omega", 2242.1}, {"index", 2}}});
  EXPECT_EQ(hbtrack::cli::fold_ending_the_stable_stretch(dir.string(), 7, shifted), 1u);
  // No fold at either end: no fold search.
  EXPECT_EQ(hbtrack::cli::fold_ending_the_stable_stretch(dir.string(), 7, json::array({lps[1]})), 0u);
  // Without stability the sides cannot be told apart: no fold search either.
  std::ofstream(dir / "branch.csv") << "omega,max_le\n2200,1\n2241,1\n2242,1\n";
  EXPECT_EQ(hbtrack::cli::fold_ending_the_stable_stretch(dir.string(), 1, lps), 0u);
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_study_comparisons
