// The study's verdict (apps/hbtrack/study_checks.cpp): "completed" only when every step
// succeeded and every limit point of every validation NFRC lies on a tracking curve.
#include <gtest/gtest.h>

#include "study_checks.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_checks {

using nlohmann::json;

namespace {

json passing_summary() {
  return {{"steps", json::array({{{"folder", "nfrc"}, {"exit_code", 0}},
                                 {{"folder", "validate_a_1"}, {"exit_code", 0}},
                                 {{"folder", "simulate"}, {"exit_code", 1}}})},
          {"simulation", {{"converged", false}}},
          {"tracking", json::array({{{"validations", json::array({{{"folder", "validate_a_1"},
                                                                   {"stop_reason", "reached_end"},
                                                                   {"limit_points", json::array({json::object(), json::object()})},
                                                                   {"lps_off_the_curves", 0}}})}}})}};
}

}  // namespace

TEST(StudyChecks, AStudyWhoseChecksHoldPasses) {
  // A time integration that ran but did not settle is a finding of the comparison, not a failure.
  EXPECT_TRUE(hbtrack::cli::failed_checks(passing_summary()).empty());
}

TEST(StudyChecks, ValidationLimitPointsOffTheCurvesFailTheStudy) {
  json s = passing_summary();
  s["tracking"][0]["validations"][0]["lps_off_the_curves"] = 1;
  const json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_NE(failed[0].get<std::string>().find("validate_a_1: 1 of its 2 limit points lie on no tracking curve"), std::string::npos)
      << failed;
}

TEST(StudyChecks, AValidationThatDidNotStartOrAFailedStepFailsTheStudy) {
  json s = passing_summary();
  s["tracking"][0]["validations"][0]["stop_reason"] = "no_convergence_at_start";
  s["steps"][1]["exit_code"] = 1;
  const json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 2u);
  EXPECT_NE(failed[0].get<std::string>().find("validate_a_1: exit 1"), std::string::npos) << failed;
  EXPECT_NE(failed[1].get<std::string>().find("no_convergence_at_start"), std::string::npos) << failed;
}

TEST(StudyChecks, ARefusedTorusIsSkippedNotFailedButOneThatStoppedFails) {
  // Exit 2 with a recorded reason: the torus refused the case's laws (docs/study.md); exit 1: it ran
  // and stopped, a finding the page must not hide.
  json s = passing_summary();
  s["steps"].push_back(
      {{"folder", "torus_ns1"}, {"exit_code", 2}, {"skipped", "torus: elements[0] (iwan): its force depends on its past"}});
  EXPECT_TRUE(hbtrack::cli::failed_checks(s).empty()) << hbtrack::cli::failed_checks(s);
  s["steps"].back() = {{"folder", "torus_ns1"}, {"exit_code", 1}};
  const json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_NE(failed[0].get<std::string>().find("torus_ns1: exit 1"), std::string::npos) << failed;
}

TEST(StudyChecks, AValidationThatLeftItsRangeIsJudgedWithItsContinuationBeyondIt) {
  json s = passing_summary();
  s["steps"][1]["exit_code"] = 1;
  json& v = s["tracking"][0]["validations"][0];
  v["stop_reason"] = "left_range";
  // Computed again over a range widened beyond its start, to the end: nothing left uncompared.
  v["beyond"] = {{"folder", "validate_a_1_beyond"}, {"stop_reason", "reached_end"}, {"omega_start", 600.0}};
  EXPECT_TRUE(hbtrack::cli::failed_checks(s).empty()) << hbtrack::cli::failed_checks(s);
  // Left the widened range too: its limit points there are not all known.
  v["beyond"]["stop_reason"] = "left_range";
  const json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 2u) << failed;
  EXPECT_NE(failed[0].get<std::string>().find("validate_a_1: exit 1"), std::string::npos) << failed;
  EXPECT_NE(failed[1].get<std::string>().find("left_range, and its continuation beyond the range left_range"), std::string::npos) << failed;
  // Without a continuation, as before.
  v.erase("beyond");
  EXPECT_EQ(hbtrack::cli::failed_checks(s).size(), 2u);
}

TEST(StudyChecks, ATimeIntegrationThatLeftTheHbmOrbitFailsTheStudy) {
  // Rotor 67, friction sense reversed: from 0.22 % above its fold the full model goes to the
  // low-amplitude branch (first harmonic 67 % below the HBM's after 200 periods). A run that has
  // not settled but stays within 10 % (the blade's 60 periods) is a finding, not a failure.
  json s = passing_summary();
  s["simulation"] = {{"converged", false},
                     {"periods", 200},
                     {"outputs", json::array({{{"name", "max_le"}, {"relative_difference", -0.168}},
                                              {{"name", "h1_le"}, {"relative_difference", -0.673}}})}};
  json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 1u) << failed;
  EXPECT_EQ(failed[0], "simulate: the time integration left the HBM orbit (h1_le -67 % off after 200 periods)");
  s["simulation"]["outputs"][1]["relative_difference"] = 0.0055;
  EXPECT_TRUE(hbtrack::cli::failed_checks(s).empty()) << hbtrack::cli::failed_checks(s);
  s["isola_simulation"] = {{"periods", 126}, {"outputs", json::array({{{"name", "h1_te"}, {"relative_difference", 0.27}}})}};
  failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 1u) << failed;
  EXPECT_NE(failed[0].get<std::string>().find("simulate_isola: the time integration left the HBM orbit (h1_te 27 %"), std::string::npos);
}

TEST(StudyChecks, TheIsolasTimeIntegrationIsJudgedByTheOrbitNotBySettling) {
  // Rotor 67 reversed: from the middle of the isola's stable stretch the integration stays within
  // 1.2 % of the HBM but has not settled after 200 periods (exit 1), as the resonance's.
  json s = passing_summary();
  s["steps"].push_back({{"folder", "simulate_isola"}, {"exit_code", 1}});
  json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 1u) << failed;  // no comparison: the run did not get as far
  EXPECT_NE(failed[0].get<std::string>().find("simulate_isola: exit 1"), std::string::npos) << failed;
  s["isola_simulation"] = {{"periods", 200}, {"outputs", json::array({{{"name", "h1_le"}, {"relative_difference", 0.012}}})}};
  EXPECT_TRUE(hbtrack::cli::failed_checks(s).empty()) << hbtrack::cli::failed_checks(s);
  s["steps"].back()["exit_code"] = 2;  // bad input is never a finding
  EXPECT_EQ(hbtrack::cli::failed_checks(s).size(), 1u);
}

TEST(StudyChecks, ANominalNfrcThatStoppedEarlyFailsTheStudy) {
  json s = passing_summary();
  s["nfrc"] = {{"stop_reason", "max_points"}, {"points", 3}};
  const json failed = hbtrack::cli::failed_checks(s);
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_NE(failed[0].get<std::string>().find("nfrc: the nominal NFRC stopped before the end of its range (max_points)"), std::string::npos)
      << failed;
  s["nfrc"]["stop_reason"] = "reached_end";
  EXPECT_TRUE(hbtrack::cli::failed_checks(s).empty());
}

}  // namespace hbtrack_tests::file_study_checks
