// `hbtrack study` end to end on a reduced-cost blade (tests/data/blade_small_study.toml: three
// contact nodes, H = 5): the nominal NFRC, the tracking of its limit points in the amplitude, the
// validation NFRCs around the cusp, whose every limit point must lie on a tracking curve, and the
// time-integration check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;
using nlohmann::json;

namespace {

const std::string kSmallBlade = hbtrack::test::source_path("tests/data/blade_small_study.toml");

using hbtrack::test::read_json;

fs::path absent_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir(name, false); }

TEST(StudyCli, SmallBladeStudyFindsTheCuspAndEveryValidationLimitPointLiesOnTheTrackingCurve) {
  const fs::path dir = absent_dir("hbtrack_study_small_blade");
  // Stability off: the study's logic does not depend on it and Hill would double the run time.
  const CliRun r = run_cli("study " + kSmallBlade + " --set stability.method=none -q -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(dir / "summary.json");
  EXPECT_EQ(s["stop_reason"], "completed");

  const json& lps = s["nfrc"]["special_points"];
  std::vector<double> lp_omega;
  for (const auto& p : lps)
    if (p["type"] == "LP") lp_omega.push_back(p["omega"].get<double>());
  ASSERT_EQ(lp_omega.size(), 2u) << "the contact resonance folds over once";

  ASSERT_EQ(s["tracking"].size(), 1u);
  const json& amplitude = s["tracking"][0];
  ASSERT_EQ(amplitude["curves"].size(), 2u);
  // The two limit points meet at the cusp, so the second lies on the first one's curve.
  EXPECT_TRUE(amplitude["curves"][0].contains("folder"));
  EXPECT_TRUE(amplitude["curves"][1].value("same_curve_as_earlier_lp", false));

  // One extremum: the cusp, a minimum of the amplitude below the nominal 40, where the fold is
  // born on the resonance that friction softens: below the linear 1B, above the lower fold.
  ASSERT_EQ(amplitude["extrema"].size(), 1u);
  const json& cusp = amplitude["extrema"][0];
  EXPECT_EQ(cusp["type"], "min");
  const double cusp_value = cusp["value"].get<double>();
  EXPECT_GT(cusp_value, 5.0);
  EXPECT_LT(cusp_value, 40.0);
  const double linear_1b = read_json(hbtrack::test::source_path("data/blade/summary.json"))["natural_frequencies"][0].get<double>();
  EXPECT_LT(cusp["omega"].get<double>(), linear_1b);
  EXPECT_GT(cusp["omega"].get<double>(), std::min(lp_omega[0], lp_omega[1]));

  // Validation NFRCs on both sides of the cusp: none of the limit points below it, two above,
  // each of them a limit point of the tracking curve at that amplitude (both are Newton
  // solutions to the case tolerance: the study's threshold is 1e-5 relative).
  ASSERT_EQ(amplitude["validations"].size(), 2u);
  const json& below = amplitude["validations"][0];
  const json& above = amplitude["validations"][1];
  EXPECT_LT(below["value"].get<double>(), cusp_value);
  EXPECT_GT(above["value"].get<double>(), cusp_value);
  EXPECT_EQ(below["limit_points"].size(), 0u);
  EXPECT_EQ(below["crossings"], 0);
  EXPECT_EQ(above["limit_points"].size(), 2u);
  for (const auto& v : amplitude["validations"]) {
    EXPECT_EQ(v["lps_off_the_curves"], 0) << "at amplitude " << v["value"];
    EXPECT_EQ(v["crossings_not_on_the_nfrc"], 0) << "no isola on this blade at amplitude " << v["value"];
    for (const auto& lp : v["limit_points"]) EXPECT_LE(lp["distance"].get<double>(), 1e-5);
  }

  // Time integration from the resonance's HBM state: two periods stay on the HBM orbit to a few
  // percent (the H = 5 truncation; tests/test_timeint_* check the integrators themselves).
  ASSERT_TRUE(s.contains("simulation"));
  for (const auto& o : s["simulation"]["outputs"]) {
    if (o["name"].get<std::string>().rfind("h1_", 0) == 0) {
      EXPECT_LT(std::abs(o["relative_difference"].get<double>()), 0.05) << o["name"];
    }
  }

  std::stringstream page;
  page << std::ifstream(dir / "index.md").rdbuf();
  EXPECT_NE(page.str().find("| amplitude | min |"), std::string::npos) << "the cusp is in the page's table";
  // The nominal NFRC's friction loop gain, one entry per contact node, in the summary and the page.
  ASSERT_TRUE(s["nfrc"].contains("friction_loop_gain"));
  EXPECT_EQ(s["nfrc"]["friction_loop_gain"].size(), 3u);
  EXPECT_NE(page.str().find("## Friction loop gain"), std::string::npos);
  // The nominal NFRC's special points in increasing omega, as the figures number them
  // (summary.json keeps the branch's order).
  {
    std::istringstream lines(page.str().substr(page.str().find("| special point | omega (rad/s) |")));
    std::string line;
    std::getline(lines, line);
    std::getline(lines, line);  // |---|
    std::vector<double> omegas;
    while (std::getline(lines, line) && line.rfind("| ", 0) == 0) {
      const std::string omega = line.substr(line.find(" | ") + 3, line.find(" | ", line.find(" | ") + 3) - line.find(" | ") - 3);
      omegas.push_back(std::stod(omega));
    }
    EXPECT_EQ(omegas.size(), s["nfrc"]["special_points"].size());
    EXPECT_TRUE(std::is_sorted(omegas.begin(), omegas.end())) << page.str();
  }
  // Two periods cannot be periodic to simulate's criterion (three confirming periods): the
  // comparison says so rather than passing the transient off as the steady state.
  EXPECT_FALSE(s["simulation"]["converged"].get<bool>());
  EXPECT_GT(s["simulation"]["last_change"].get<double>(), 0.0);
  EXPECT_NE(page.str().find("Not periodic to `simulate`'s criterion"), std::string::npos);
  // The figures need Debian's python3-matplotlib, which the install script provides.
  const std::vector<std::string> figures = s["figures"].get<std::vector<std::string>>();
  for (const char* expected :
       {"figures/nfrc.png", "figures/tracking_amplitude.png", "figures/validation_amplitude.png", "figures/simulation_signals.png"})
    EXPECT_NE(std::find(figures.begin(), figures.end(), expected), figures.end()) << expected;
  for (const auto& f : figures) EXPECT_GT(fs::file_size(dir / f), 1000u) << f;
  fs::remove_all(dir);
}

TEST(StudyCli, BadStudyInputGivesOneLineErrors) {
  const fs::path dir = absent_dir("hbtrack_study_bad");
  const CliRun no_study = run_cli("study " + hbtrack::test::source_path("examples/duffing.toml") + " -o " + dir.string());
  EXPECT_EQ(no_study.exit_code, 2);
  EXPECT_NE(no_study.err.find("study.track: missing"), std::string::npos) << no_study.err;
  const CliRun only = run_cli("study " + kSmallBlade + " --only clearance -o " + dir.string());
  EXPECT_EQ(only.exit_code, 2);
  EXPECT_NE(only.err.find("--only: 'clearance' is not tracked"), std::string::npos) << only.err;
  const CliRun range = run_cli("study " + kSmallBlade + " --set amplitude=70 -o " + dir.string());
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_NE(range.err.find("study.track[0].range: must contain the case's amplitude"), std::string::npos) << range.err;
  const CliRun ns_pd = run_cli("study " + kSmallBlade + " --set study.track_ns_pd=1 -o " + dir.string());
  EXPECT_EQ(ns_pd.exit_code, 2);
  EXPECT_NE(ns_pd.err.find("study.track_ns_pd: expected true or false"), std::string::npos) << ns_pd.err;
  // An adaptive-harmonics case: refused before its nominal NFRC (only frc changes H; the study's
  // tracking step would refuse it after that NFRC), naming the file and the field.
  const CliRun adaptive = run_cli(
      "study " + kSmallBlade + " --set harmonic_balance.harmonics=3 --set 'harmonic_balance.adaptive={min=3, max=9}' -o " + dir.string());
  EXPECT_EQ(adaptive.exit_code, 2);
  EXPECT_NE(adaptive.err.find(kSmallBlade + ": harmonic_balance.adaptive: a study holds one H"), std::string::npos) << adaptive.err;
  EXPECT_FALSE(fs::exists(dir / "nfrc" / "summary.json"));
  for (const CliRun& run : {no_study, only, range, ns_pd, adaptive})
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  fs::remove_all(dir);
}

// DIR/case.toml: the example's case with a [study] section of these lines.
void write_example_with_study(const fs::path& dir, const std::string& example, const std::string& study_lines) {
  fs::create_directories(dir);
  std::ifstream in(hbtrack::test::source_path(example));
  std::ofstream out(dir / "case.toml");
  out << in.rdbuf() << "\n[study]\n" << study_lines;
}

}  // namespace

TEST(StudyCli, WithTrackNsPdTheStudyFollowsEveryNsPointAndListsItsCurves) {
  // The nonlinear absorber (examples/nltva.toml) has two NS points on its nominal NFRC. Each is
  // followed in the amplitude from that very point, to both ends of its curve on a fold (NS
  // frequency 0, as `track --ns` alone: tests/test_ns_tracking.cpp), and listed on the page; the
  // limit points' validations still all pass (NS curves start no validation or isola search).
  const fs::path dir = absent_dir("hbtrack_study_ns_pd");
  write_example_with_study(dir, "examples/nltva.toml",
                           "track = [ { parameter = \"amplitude\", range = [0.05, 0.35] } ]\nsimulate_periods = 0\ntrack_ns_pd = true\n");
  const CliRun r = run_cli("study " + (dir / "case.toml").string() + " -q -o " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(dir / "out" / "summary.json");
  const json nfrc = read_json(dir / "out" / "nfrc" / "summary.json");
  std::vector<double> ns_omegas;
  for (const auto& sp : nfrc["special_points"])
    if (sp["type"] == "NS") ns_omegas.push_back(sp["omega"].get<double>());
  std::sort(ns_omegas.begin(), ns_omegas.end());
  ASSERT_EQ(ns_omegas.size(), 2u);
  std::ifstream page(dir / "out" / "index.md");
  std::stringstream text;
  text << page.rdbuf();
  for (size_t k = 0; k < 2; ++k) {
    const std::string name = "NS" + std::to_string(k + 1), folder = "track_amplitude_ns" + std::to_string(k + 1);
    const auto& curves = s["tracking"][0]["curves"];
    const auto curve = std::find_if(curves.begin(), curves.end(), [&](const json& c) { return c.value("point", "") == name; });
    ASSERT_NE(curve, curves.end()) << name;
    EXPECT_EQ((*curve)["folder"], folder);
    EXPECT_EQ((*curve)["stop_reason"], "completed");
    const auto branch = hbtrack::test::csv_records(dir / "out" / folder / "branch.csv");
    EXPECT_NEAR(branch.front().at("omega"), ns_omegas[k], 1e-12 * ns_omegas[k]);  // started on the NFRC's own NS point
    EXPECT_EQ(branch.front().at("amplitude"), 0.12);
    int ends_on_a_fold = 0;
    const json track = read_json(dir / "out" / folder / "summary.json");
    for (const auto& sp : track["special_points"]) ends_on_a_fold += sp["type"] == "resonance_1_1";
    EXPECT_EQ(ends_on_a_fold, 2) << name;
    EXPECT_NE(text.str().find("| " + name + " |"), std::string::npos) << name;
  }
  fs::remove_all(dir);
}

TEST(StudyCli, AStudyWhoseValidationFailsExitsOneAndSaysSoFirst) {
  // The Duffing oscillator's limit points tracked in the amplitude with at most 4 points a leg:
  // the curves stop near the start, so the validation NFRC at amplitude 2.5 (the case's
  // `validate`) has limit points on no tracking curve, and none may start a curve of its own
  // (max_added_curves = 0). The study must not say "completed".
  const fs::path dir = absent_dir("hbtrack_study_failing");
  write_example_with_study(dir, "examples/duffing.toml",
                           "track = [ { parameter = \"amplitude\", range = [0.5, 3.0], validate = [2.5] } ]\nmax_points = 4\n"
                           "simulate_periods = 0\nmax_added_curves = 0\n");
  const CliRun r = run_cli("study " + (dir / "case.toml").string() + " -q -o " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("check(s) failed"), std::string::npos) << r.err;
  const json s = read_json(dir / "out" / "summary.json");
  EXPECT_EQ(s["stop_reason"], "checks_failed");
  ASSERT_FALSE(s["failed_checks"].empty());
  EXPECT_NE(s["failed_checks"][0].get<std::string>().find("lie on no tracking curve"), std::string::npos);
  std::ifstream page(dir / "out" / "index.md");
  std::stringstream text;
  text << page.rdbuf();
  const std::string index = text.str();
  EXPECT_NE(index.find("Status: checks_failed"), std::string::npos);
  // The failed checks come before the first figure.
  EXPECT_LT(index.find("## Failed checks"), index.find("!["));
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_study_cli
