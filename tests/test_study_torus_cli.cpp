// `hbtrack study` with [study] torus (docs/study.md): on the nonlinear absorber, whose nominal NFRC
// has one unstable band between NS points at 1.10958 and 1.22470 rad/s, the torus born at the
// lower one is a step of the study (torus_ns1/, as `hbtrack torus --ns 1`) that closes at the
// other, listed on the page and kept by --resume; a torus the case's laws rule out is skipped
// with its reason, the study completed; bad keys refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_torus_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::read_json;
using hbtrack::test::run_cli;
using nlohmann::json;

namespace {

// The absorber with a [study] section of these lines.
fs::path write_absorber_study(const fs::path& dir, const std::string& study) {
  fs::create_directories(dir);
  std::ofstream(dir / "case.toml") << hbtrack::test::file_bytes(hbtrack::test::source_path("examples/nltva.toml")) << "\n[study]\n"
                                   << study;
  return dir / "case.toml";
}

// The omegas of the NFRC's NS points, in increasing omega (`torus --ns K` counts them so).
std::vector<double> ns_omegas(const fs::path& nfrc) {
  std::vector<double> omegas;
  const json summary = read_json(nfrc / "summary.json");
  for (const auto& sp : summary["special_points"])
    if (sp["type"] == "NS") omegas.push_back(sp["omega"].get<double>());
  std::sort(omegas.begin(), omegas.end());
  return omegas;
}

const json* step_of(const json& summary, const std::string& folder) {
  for (const auto& s : summary["steps"])
    if (s["folder"] == folder) return &s;
  return nullptr;
}

}  // namespace

TEST(StudyTorusCli, TheTorusBornAtTheBandsLowerNsPointClosesAtTheOtherAndResumeKeepsIt) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_study_torus", true);
  // The least grid alias-free for the cubic springs (N > 4 H): a third of the default 64 x 32's
  // time, its last row within 1e-7 of the default's.
  const std::string study = write_absorber_study(dir, "torus = { samples = [32, 17] }\nsimulate_periods = 0\n").string();
  const fs::path out = dir / "out";
  const CliRun r = run_cli("study " + study + " -q --jobs 1 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> ns = ns_omegas(out / "nfrc");
  ASSERT_EQ(ns.size(), 2u);

  // The branch starts on the NS point itself (row 0) and ends at the other, within the 3e-5 in
  // omega the torus docs give (its last row is the one before its size changes sign).
  const auto branch = hbtrack::test::csv_records(out / "torus_ns1" / "branch.csv");
  ASSERT_GT(branch.size(), 10u);
  EXPECT_NEAR(branch.front().at("omega"), ns[0], 1e-12 * ns[0]);
  EXPECT_EQ(branch.front().at("size"), 0.0);
  EXPECT_NEAR(branch.back().at("omega"), ns[1], 3e-5);
  const json torus = read_json(out / "torus_ns1" / "summary.json");
  EXPECT_EQ(torus["stop_reason"], "reached_ns_point");
  EXPECT_EQ(torus["options"]["torus"]["samples"], json({32, 17}));

  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "completed");
  ASSERT_EQ(s["tori"].size(), 1u);
  const json& t = s["tori"][0];
  EXPECT_EQ(t["folder"], "torus_ns1");
  EXPECT_EQ(t["ns"], 1);
  EXPECT_EQ(t["other_ns"], 2);
  EXPECT_EQ(t["closed_at_ns"], 2);
  EXPECT_LT(t["closed_at_distance"].get<double>(), 3e-5);
  EXPECT_EQ(t["points"], branch.size());
  ASSERT_EQ(t["envelope"].size(), 2u);  // x1, x2: the torus' largest motion, above the periodic one
  double largest_x2 = 0;
  for (const auto& row : branch) largest_x2 = std::max(largest_x2, row.at("max_x2"));
  EXPECT_EQ(t["envelope"][1]["name"], "x2");
  EXPECT_EQ(t["envelope"][1]["max"].get<double>(), largest_x2);
  EXPECT_GT(largest_x2, branch.front().at("max_x2"));
  const std::string page = hbtrack::test::file_bytes(out / "index.md");
  EXPECT_NE(page.find("## Quasi-periodic response (tori)"), std::string::npos) << page;
  EXPECT_NE(page.find("[torus_ns1](torus_ns1/) | " + std::to_string(branch.size()) + " | closed at NS2"), std::string::npos) << page;

  // Stopped after its steps (as during its figures), the study resumed keeps the torus as it is.
  json stopped = s;
  stopped["stop_reason"] = "interrupted";
  std::ofstream(out / "summary.json") << stopped.dump();
  const std::string torus_rows = hbtrack::test::file_bytes(out / "torus_ns1" / "branch.csv");
  const CliRun resumed = run_cli("study " + study + " --jobs 1 --resume " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("torus_ns1" + std::string(18, ' ') + "done before, kept"), std::string::npos) << resumed.err;
  EXPECT_EQ(read_json(out / "summary.json")["resumed_steps"], 2);
  EXPECT_EQ(hbtrack::test::file_bytes(out / "torus_ns1" / "branch.csv"), torus_rows);
  EXPECT_EQ(read_json(out / "summary.json")["tori"], s["tori"]);
  fs::remove_all(dir);
}

TEST(StudyTorusCli, ATorusTheLawsRuleOutIsSkippedWithItsReasonAndTheStudyCompletes) {
  // A Lanczos filter on the absorber's spring: the NFRC keeps its band, the torus refuses the
  // filter (exit 2 of `hbtrack torus`): the step is recorded as skipped, not failed.
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_study_torus_skipped", true);
  const std::string study = write_absorber_study(dir, "torus = true\nsimulate_periods = 0\n").string();
  const fs::path out = dir / "out";
  const CliRun r = run_cli("study " + study + " -q --jobs 1 --set elements[1].lanczos=1 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(ns_omegas(out / "nfrc").size(), 2u);
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "completed");
  EXPECT_TRUE(s["failed_checks"].empty()) << s["failed_checks"];
  ASSERT_EQ(s["tori"].size(), 1u);
  const std::string reason = "elements[1] (cubic_spring): it has a Lanczos filter (lanczos = 0 for a torus)";
  EXPECT_NE(s["tori"][0]["skipped"].get<std::string>().find(reason), std::string::npos) << s["tori"][0];
  const json* step = step_of(s, "torus_ns1");
  ASSERT_NE(step, nullptr);
  EXPECT_EQ((*step)["exit_code"], 2);
  EXPECT_EQ((*step)["skipped"], s["tori"][0]["skipped"]);
  const std::string page = hbtrack::test::file_bytes(out / "index.md");
  EXPECT_NE(page.find("| torus_ns1 | | skipped: "), std::string::npos) << page;
  EXPECT_NE(page.find("| torus_ns1 | 2 (skipped) |"), std::string::npos) << page;

  // Resumed, the skipped step is kept as skipped (it would be refused again).
  json stopped = s;
  stopped["stop_reason"] = "interrupted";
  std::ofstream(out / "summary.json") << stopped.dump();
  const CliRun resumed = run_cli("study " + study + " -q --jobs 1 --set elements[1].lanczos=1 --resume " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const json again = read_json(out / "summary.json");
  EXPECT_EQ(again["resumed_steps"], 2);
  EXPECT_EQ(again["tori"], s["tori"]);
  fs::remove_all(dir);
}

TEST(StudyTorusCli, BadTorusKeysGiveOneLineErrorsNamingFileFieldAndRule) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_study_torus_bad", true);
  const struct {
    std::string study, expected;
  } cases[] = {
      {"torus = 1\n", "study.torus: expected true or false, or a table {harmonics = [H1, H2], samples = [N1, N2]}"},
      {"torus = { harmonics = [0, 4] }\n", "study.torus.harmonics: must be [H1, H2] with 1 <= H1, H2 <= 64"},
      {"torus = { harmonics = [5, 65] }\n", "study.torus.harmonics: must be [H1, H2] with 1 <= H1, H2 <= 64"},
      {"torus = { harmonics = [5] }\n", "study.torus.harmonics: expected two integers [A, B]"},
      {"torus = { harmonics = [5, 4.5] }\n", "study.torus.harmonics[1]: expected an integer"},
      {"torus = { samples = [64, 8] }\n", "study.torus.samples: must be [N1, N2] with N1 >= 2 H1 + 1 = 11 and N2 >= 2 H2 + 1 = 9"},
      {"torus = { harmonics = [7, 2], samples = [14, 5] }\n",
       "study.torus.samples: must be [N1, N2] with N1 >= 2 H1 + 1 = 15 and N2 >= 2 H2 + 1 = 5"},
      {"torus = { harmonic = [5, 4] }\n", "study.torus.harmonic: unknown key (did you mean 'harmonics'?)"},
      {"torus = false\n", "study.track: missing"},
  };
  for (const auto& c : cases) {
    const std::string study = write_absorber_study(dir, c.study).string();
    const CliRun r = run_cli("study " + study + " -o " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << c.study << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.study << r.err;
    EXPECT_NE(r.err.find("case.toml"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "nfrc")) << c.study;  // refused before any step
  }
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_study_torus_cli
