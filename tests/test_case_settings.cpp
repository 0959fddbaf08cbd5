// with_overrides: `--set` on a case already read gives the case that `--set` on its file gives,
// refuses what the file's reader refuses with the same message, and leaves the case alone.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_case_settings {

using namespace hbtrack;

namespace {

// Every setting a run reads, as summary.json writes them.
nlohmann::json settings_of(const CaseDefinition& c) {
  const HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  return options_json(c, hbm);
}

std::string error_of(const CaseDefinition& c, const std::vector<std::string>& overrides) {
  try {
    with_overrides(c, overrides);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

const std::string kDuffing = test::source_path("examples/duffing.toml");

}  // namespace

TEST(CaseSettings, OverridesOnACaseGiveWhatSetOnTheFileGives) {
  // A step below the default step_min moves step_min with it, as the file's reader does.
  const std::vector<std::string> overrides{"amplitude=2.5", "harmonic_balance.harmonics=[1, 3, 5]", "continuation.step=1e-8",
                                           "continuation.omega_end=2.0", "stability.method=\"monodromy\""};
  const CaseDefinition plain = load_case(kDuffing);
  const CaseDefinition changed = with_overrides(plain, overrides);
  EXPECT_EQ(settings_of(changed), settings_of(load_case(kDuffing, overrides)));
  EXPECT_EQ(changed.nfrc.continuation.step_min, 1e-8);
  EXPECT_EQ(settings_of(plain), settings_of(load_case(kDuffing)));  // the case itself is unchanged
}

TEST(CaseSettings, RefusesWhatTheCaseFileRefuses) {
  const CaseDefinition c = load_case(kDuffing);
  EXPECT_EQ(error_of(c, {"continuation.omega_strat=0.5"}), "--set: continuation.omega_strat: unknown key (did you mean 'omega_start'?)");
  EXPECT_EQ(error_of(c, {"amplitdue=2"}), "--set amplitdue: unknown parameter (did you mean 'amplitude'?)");
  EXPECT_NE(error_of(c, {"continuation.step=-1"}).find("continuation.step"), std::string::npos);
  EXPECT_NE(error_of(c, {"harmonic_balance.harmonics=0"}).find("harmonic_balance.harmonics"), std::string::npos);
  EXPECT_NE(error_of(c, {"elements[0].cubic_stiffness=2"}).find("'elements' is the case's"), std::string::npos);
}

}  // namespace hbtrack_tests::file_case_settings
