// The warnings that name special points and tracking extrema the time sampling, not the
// dynamics, produced (src/runs/artefact_warnings.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "hbtrack/runs/artefact_warnings.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_artefact_warnings {

using namespace hbtrack;

namespace {

// Types by their names, as summary.json lists them: the tables below read as a result does.
SpecialPoint special(const char* type, double omega) {
  SpecialPoint p;
  p.type = parse_special_point_type(type);
  p.lambda = omega;
  return p;
}

FoldExtremum extremum(const char* type, int index, double omega, double parameter) {
  FoldExtremum e;
  e.type = parse_curve_extremum_type(type);
  e.index = index;
  e.omega = omega;
  e.parameter = parameter;
  return e;
}

}  // namespace

TEST(ArtefactWarnings, FourSpecialPointsWithinATenthOfAPercentOfTheRangeAreACluster) {
  // Range 1: spacing 1e-4 is a cluster; two genuine folds 0.1 apart are not.
  const std::vector<SpecialPoint> saw_tooth{special("LP", 0.7),    special("LP", 0.7001), special("NS", 0.7002),
                                            special("LP", 0.7003), special("LP", 0.9),    special("LP", 1.0)};
  const auto warnings = runs::special_point_clusters(saw_tooth, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("4 special points (3 LP, 1 NS)"), std::string::npos) << warnings[0];
  EXPECT_TRUE(runs::special_point_clusters({special("LP", 0.7), special("LP", 0.8), special("PD", 0.9)}, 1.0).empty());
}

TEST(ArtefactWarnings, AMinNextToAMaxAtTheSameParameterIsAWiggleNotABirthAndAMerge) {
  // A birth at mu = 0.1 and a merge at 0.5 are genuine; the min/max pair 1e-5 apart in mu and
  // in omega (range 1, span 0.4) is not.
  const std::vector<FoldExtremum> extrema{extremum("min", 3, 1.0, 0.1), extremum("max", 40, 1.2, 0.3),
                                          extremum("min", 41, 1.20001, 0.29999), extremum("max", 90, 1.4, 0.5)};
  const auto warnings = runs::extremum_pairs_below_resolution(extrema, "mu", 1.0, 0.4);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 min/max pair of mu"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("mu = 0.3 at omega = 1.2"), std::string::npos) << warnings[0];
  // Far apart in omega (a cusp's two sides), or of the same type: no warning.
  EXPECT_TRUE(
      runs::extremum_pairs_below_resolution({extremum("max", 40, 1.2, 0.3), extremum("min", 41, 1.3, 0.29999)}, "mu", 1.0, 0.4).empty());
  EXPECT_TRUE(runs::extremum_pairs_below_resolution({extremum("max", 1, 1.2, 0.3), extremum("max", 2, 1.2, 0.3)}, "mu", 1.0, 0.4).empty());
}

TEST(ArtefactWarnings, AClusterWhoseLimitPointsStayWhenRecomputedIsNoArtefact) {
  // Four folds 1e-4 apart (range 1): recomputed where they are (within a tenth of their 1e-4
  // spacing) they are no sampling artefact; moved by more, fewer, or a failed run: reported.
  const std::vector<SpecialPoint> folds{special("LP", 0.7), special("LP", 0.7001), special("LP", 0.7002), special("LP", 0.7003)};
  auto returning = [](std::optional<std::vector<double>> omegas) {
    return [omegas](const std::vector<const SpecialPoint*>&) { return omegas; };
  };
  EXPECT_TRUE(runs::special_point_clusters(folds, 1.0, returning(std::vector<double>{0.70030, 0.700001, 0.70010, 0.70020})).empty());
  EXPECT_EQ(runs::special_point_clusters(folds, 1.0, returning(std::vector<double>{0.7, 0.7001, 0.7002, 0.70032})).size(), 1u)
      << "one moved by 2e-5, a fifth of the spacing";
  EXPECT_EQ(runs::special_point_clusters(folds, 1.0, returning(std::vector<double>{0.7, 0.7001})).size(), 1u) << "two vanished";
  EXPECT_EQ(runs::special_point_clusters(folds, 1.0, returning(std::nullopt)).size(), 1u) << "the recomputation failed";
  // PD and NS points are not recomputed: a cluster holding one is reported, whatever the check.
  std::vector<SpecialPoint> with_ns = folds;
  with_ns[1] = special("NS", 0.7001);
  EXPECT_EQ(runs::special_point_clusters(with_ns, 1.0, returning(std::vector<double>{0.7, 0.7001, 0.7002, 0.7003})).size(), 1u);
}

TEST(ArtefactWarnings, TheThreeOscillatorFoldsStayAndTheCoarseDlftSawToothIsReported) {
  // NLvib's three-oscillator example: 4 folds within omega 1.62634-1.62809 were called "most
  // likely artefacts of the time sampling"; recomputed with 4 times the samples and a quarter of
  // the steps they stay within 1e-6 rad/s, so no warning. The DLFT example at N = 2H + 1 = 11
  // folds dozens of times within 1e-3: recomputed, those folds vanish, and it is reported.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "a minute under the sanitizers; run by the Release pass";
  namespace fs = std::filesystem;
  const fs::path base = hbtrack::test::fresh_temp_dir("hbtrack_artefact_cli");
  const std::string oscillators = "frc " + hbtrack::test::source_path("examples/three_oscillators_jenkins.toml") + " -q -o ";
  ASSERT_EQ(hbtrack::test::run_cli(oscillators + (base / "three").string()).exit_code, 0);
  const nlohmann::json three = hbtrack::test::read_json((base / "three" / "summary.json").string());
  int folds_near = 0;
  for (const auto& p : three["special_points"])
    if (p["type"] == "LP" && p["omega"].get<double>() > 1.626 && p["omega"].get<double>() < 1.629) ++folds_near;
  EXPECT_EQ(folds_near, 4);
  int sticking = 0;
  for (const auto& w : three["warnings"]) {
    EXPECT_EQ(w.get<std::string>().find("artefacts of the time sampling"), std::string::npos) << w;
    // Where the paths of hbtrack and NLvib part (docs/elements.md): the x2 - x1 slider stuck off
    // rest, from the stretch before the fold cluster through the upper fold.
    if (w.get<std::string>().find("elements[1] (elastic_dry_friction) sticks for the whole period") != std::string::npos) ++sticking;
  }
  EXPECT_EQ(sticking, 1);
  const std::string dlft = "frc " + hbtrack::test::source_path("examples/frictional_contact_dlft.toml") +
                           " --set harmonic_balance.samples=11 -q -o " + (base / "dlft").string();
  hbtrack::test::run_cli(dlft);  // exit 1 or 0: it runs out of max_points in the saw-tooth
  const nlohmann::json coarse = hbtrack::test::read_json((base / "dlft" / "summary.json").string());
  int clusters = 0;
  for (const auto& w : coarse["warnings"]) clusters += w.get<std::string>().find("artefacts of the time sampling") != std::string::npos;
  EXPECT_GE(clusters, 1);
  fs::remove_all(base);
}

}  // namespace hbtrack_tests::file_artefact_warnings
