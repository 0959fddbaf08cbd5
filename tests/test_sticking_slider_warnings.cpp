// Sliders stuck for the whole period off their rest position, where the periodic problem leaves
// their position free (src/runs/sticking_slider_warnings.cpp, docs/elements.md).
#include <gtest/gtest.h>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "hbtrack/runs/sticking_slider_warnings.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_sticking_slider_warnings {

using namespace hbtrack;

namespace {

// A branch point of NLvib's three-oscillator case (H = 7, dofs x1, x2, x3, no condensation:
// unknowns harmonic-major [a0, a1, b1, ...] x 3) with x1 = mean + a cos(tau), x2 = x1 + b cos(tau).
BranchPoint motion(double mean, double a, double b) {
  BranchPoint p;
  p.lambda = 1.59;
  p.u = Eigen::VectorXd::Zero(3 * 15);
  p.u(0) = 2 * mean;  // a0 of x1, twice the mean
  p.u(1) = 2 * mean;  // x2 rides on x1
  p.u(3 + 0) = a;
  p.u(3 + 1) = a + b;
  return p;
}

}  // namespace

TEST(StickingSliderWarnings, OnlyASliderStuckOffRestIsReported) {
  CaseDefinition c = load_case(test::source_path("examples/three_oscillators_jenkins.toml"));
  HarmonicBalance hbm = runs::make_system(c);
  // Jenkins k = 20, F = 1: a slider sticks while the range of d stays below 2 F / k = 0.1.
  // elements[0] on x1: range 0.02, midrange 0.2: stuck off rest. elements[1] on x2 - x1:
  // range 0.4: slips.
  auto warnings = runs::sticking_slider_warnings(hbm, {motion(0.2, 0.01, 0.2), motion(0.19, 0.01, 0.2)});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("elements[0] (elastic_dry_friction)"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("by up to 0.2) at 2 points"), std::string::npos) << warnings[0];
  // elements[1] stuck too (b = 0: d = 0, range 0), but at rest: nothing to choose.
  warnings = runs::sticking_slider_warnings(hbm, {motion(0.2, 0.01, 0.0)});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("elements[0]"), std::string::npos) << warnings[0];
  // Centred (mean 0) or slipping (range 0.2): no warning.
  EXPECT_TRUE(runs::sticking_slider_warnings(hbm, {motion(0.0, 0.01, 0.2), motion(0.2, 0.1, 0.2)}).empty());
  // Off rest by less than kOffRestFraction of the range (0.02): still no warning.
  EXPECT_TRUE(runs::sticking_slider_warnings(hbm, {motion(0.5 * runs::kOffRestFraction * 0.02, 0.01, 0.2)}).empty());
}

}  // namespace hbtrack_tests::file_sticking_slider_warnings
