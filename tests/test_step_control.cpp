// The step controller sizes steps by the branch (turn per step, corrector work, special points
// ahead) instead of spacing points at step_max: fewer points, the same special points. The
// references are the special points that the controller it replaced (steps capped at
// step_max = 0.1, main at d2aa3d1) found with each example's own settings, from `hbtrack frc`.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "special_point_reference.hpp"
#include "test_support.hpp"

using namespace hbtrack;

namespace hbtrack_tests::file_step_control {
namespace {

using Reference = SpecialPointReference;

// The special points of the example's NFRC with its own settings, in the order found.
void expect_same_special_points(const std::string& example, const std::vector<Reference>& reference, int points_before) {
  const CaseDefinition c = load_case(test::source_path("examples/" + example));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  // They agreed within 5e-10 relative when the references were taken.
  expect_special_points_near(r.continuation.special_points, reference, example);
  // Not a result, the point of the controller: the cap no longer sets the spacing.
  EXPECT_LT(r.continuation.summary.points, points_before) << example;
}

}  // namespace

TEST(StepControlContinuation, DuffingLimitPointsAsWithTheCappedStep) {
  expect_same_special_points("duffing.toml", {{"LP", 1.2696019555361926}, {"LP", 1.1157002517693952}}, 83);
}

TEST(StepControlContinuation, NltvaLimitAndNeimarkSackerPointsAsWithTheCappedStep) {
  expect_same_special_points(
      "nltva.toml", {{"NS", 1.1095773849480641}, {"NS", 1.2246986203791512}, {"LP", 1.233412335048531}, {"LP", 1.217937015063664}}, 133);
}

TEST(StepControlContinuation, ChainContactLimitPointsAsWithTheCappedStep) {
  // 13 s in Release; under the sanitizers more than 8 minutes with a second job on the cores
  // (a CI run timed out at 600 s): the Release pass checks the points, the sanitizer pass runs the
  // same controller on Duffing and the absorber above.
  if (test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers; run by the Release pass";
  expect_same_special_points("chain_contact.toml", {{"LP", 0.21294243411684077}, {"LP", 0.20581564895593368}}, 105);
}

TEST(StepControlContinuation, TwoDofContactLimitAndPeriodDoublingPointsAsWithTheCappedStep) {
  // Shooting at every point (the cross-check on this C0 law): 4 s in Release, a minute under the
  // sanitizers, whose pass runs the same controller on the three examples above.
  if (test::kSanitizedBuild) GTEST_SKIP() << "a minute under the sanitizers; run by the Release pass";
  expect_same_special_points("two_dof_contact.toml",
                             {{"PD", 0.6670935184695566},
                              {"PD", 0.6865314453305182},
                              {"PD", 0.76369484688166},
                              {"PD", 0.7690640117785776},
                              {"LP", 0.7700769838080966},
                              {"LP", 0.6892886411491028},
                              {"PD", 1.6080943284506604},
                              {"PD", 1.6250494822363846}},
                             194);
}

}  // namespace hbtrack_tests::file_step_control
