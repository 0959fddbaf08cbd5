// The element library's example cases (docs/elements.md) run with `hbtrack frc` as the README
// says: each NFRC reaches the end of its range (three_oscillators_jenkins: test_jenkins.cpp).
#include <gtest/gtest.h>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_element_examples {

using namespace hbtrack;

class ElementExample : public testing::TestWithParam<const char*> {};

TEST_P(ElementExample, NfrcReachesTheEndOfItsRange) {
  // Under the sanitizers Hill alone decides stability: the cross-check (shooting or the
  // monodromy matrix at every point of these small non-smooth or hysteretic models) takes minutes
  // there, and it does not change where the continuation goes. The Release pass runs the
  // defaults; the cross-check runs under the sanitizers in test_stability_contact.cpp and
  // test_history_time_stepping.cpp.
  std::vector<std::string> sets;
  if (test::kSanitizedBuild) sets.push_back("stability.cross_check=\"off\"");
  CaseDefinition c = load_case(test::source_path(std::string("examples/") + GetParam()), sets);
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
  EXPECT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  ASSERT_FALSE(r.recorded.empty());
  EXPECT_NEAR(r.recorded.back().omega, c.nfrc.omega_end, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Cases, ElementExample,
                         testing::Values("polynomial_and_power_damper.toml", "frictional_contact.toml", "iwan_joint.toml",
                                         "planar_jenkins.toml", "element_directions.toml", "frictional_contact_2d.toml",
                                         "tip_stick_slip.toml"),
                         [](const testing::TestParamInfo<const char*>& param) {
                           std::string name = param.param;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace hbtrack_tests::file_element_examples
