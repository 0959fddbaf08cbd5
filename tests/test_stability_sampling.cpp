// Stability where the verdict can change (stability.every_point = false, the default on models
// of more than 12 dofs): on the blade and on rotor 67 in both friction senses, every point the
// monitor skipped has the stable flag Hill's method gives at that very point, and the special
// points are those Hill at every point finds. The references are `hbtrack frc CASE --set
// stability.every_point=true` on these examples (main at 9870a07's successor, this change).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "special_point_reference.hpp"
#include "test_support.hpp"

using namespace hbtrack;

namespace hbtrack_tests::file_stability_sampling {
namespace {

using Reference = SpecialPointReference;

// Runs the example's NFRC with its own settings (stability sampled), then Hill at every point
// it skipped.
void expect_hill_verdicts_and_special_points(const std::string& example, const std::vector<std::string>& overrides,
                                             const std::vector<Reference>& reference) {
  const CaseDefinition c = load_case(test::source_path("examples/" + example), overrides);
  ASSERT_FALSE(c.nfrc.stability.every_point);
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  ASSERT_EQ(r.recorded.size(), r.continuation.points.size());
  int skipped = 0;
  for (size_t i = 0; i < r.recorded.size(); ++i) {
    if (r.recorded[i].stability_method != kBracketedStability) continue;
    ++skipped;
    const BranchPoint& p = r.continuation.points[i];
    const FloquetResult hill = floquet(hbm, p.u, p.lambda, c.nfrc.stability);
    EXPECT_EQ(r.recorded[i].stable, hill.stable ? 1 : 0) << example << " point " << i << " omega " << p.lambda;
  }
  // Not a result, the point of sampling: the verdict comes from its neighbours somewhere.
  EXPECT_GT(skipped, static_cast<int>(r.recorded.size()) / 5) << example;
  // They agreed to round-off when the references were taken.
  expect_special_points_near(r.continuation.special_points, reference, example);
}

std::vector<std::string> reversed_friction() {
  std::vector<std::string> out;
  for (int k = 0; k < 9; ++k) out.push_back("elements[" + std::to_string(k) + "].engine_order=1");
  return out;
}

}  // namespace

// Seconds each in Release, minutes under the sanitizers, whose pass runs the engine's side of
// sampling in test_lazy_monitor.cpp.
TEST(StabilitySampling, BladeVerdictsAreHillsAtEveryPoint) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "the blade's NFRC: run by the Release pass";
  expect_hill_verdicts_and_special_points("blade/nominal.toml", {}, {{"LP", 2028.0106803917504}, {"LP", 1827.4366048120314}});
}

TEST(StabilitySampling, Rotor67VerdictsAreHillsAtEveryPoint) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "rotor 67's NFRC: run by the Release pass";
  expect_hill_verdicts_and_special_points("rotor67/nominal.toml", {},
                                          {{"LP", 2242.0732716564385},
                                           {"NS", 2238.1095632101947},
                                           {"NS", 2221.3574186233486},
                                           {"LP", 1659.2894601697062},
                                           {"NS", 2089.3955446094055},
                                           {"NS", 2172.1190976828016}});
}

TEST(StabilitySampling, Rotor67ReversedFrictionVerdictsAreHillsAtEveryPoint) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "rotor 67's NFRC: run by the Release pass";
  expect_hill_verdicts_and_special_points("rotor67/nominal.toml", reversed_friction(),
                                          {{"NS", 2406.760721802651},
                                           {"NS", 2425.3079909829421},
                                           {"LP", 2430.04953859134},
                                           {"LP", 2272.8535107708503},
                                           {"LP", 2479.8642538595172},
                                           {"LP", 2358.4756324454484}});
}

}  // namespace hbtrack_tests::file_stability_sampling
