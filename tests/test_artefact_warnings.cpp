// The warnings that name special points and tracking extrema the time sampling, not the
// dynamics, produced (src/runs/artefact_warnings.cpp).
#include <gtest/gtest.h>

#include "hbtrack/runs/artefact_warnings.hpp"

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

}  // namespace hbtrack_tests::file_artefact_warnings
