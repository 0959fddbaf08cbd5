// `hbtrack study` with [study] backbone and switch (docs/study.md): on the coupled Duffing
// oscillators, the backbone of the in-phase mode and the branches born at the NFRC's branch
// points, each a step into its own folder, listed on the page and drawn in the NFRC figure
// (what the figure holds: python/tests/test_analysis_figures.py); bad keys refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_branches_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;
using nlohmann::json;

namespace {

using hbtrack::test::read_json;

fs::path empty_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir(name, true); }

const std::string kCoupled = hbtrack::test::source_path("examples/coupled_duffing.toml");

// The coupled Duffing example with another [study] section.
fs::path write_case(const fs::path& dir, const std::string& study) {
  const std::string example = hbtrack::test::file_bytes(kCoupled);
  std::ofstream(dir / "case.toml") << example.substr(0, example.find("\n[study]") + 1) << "[study]\n" << study;
  return dir / "case.toml";
}

json without_timing_fields(json j) {
  if (j.is_object()) {
    for (const char* key : {"wall_s", "timings", "resumed_steps", "jobs", "runner"}) j.erase(key);
    for (auto& [key, value] : j.items()) value = without_timing_fields(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_timing_fields(value);
  }
  return j;
}

}  // namespace

TEST(StudyBranchesCli, BackboneAndSwitchedBranchesAreStepsOnThePageAndInTheFigure) {
  // The study runs an NFRC, a backbone and a switch or two: seconds in Release, minutes under
  // the sanitizers, where the bad-key test below runs the same reader and the verbs' own tests
  // run the computations.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "a study of several verbs; the Release pass runs it";
  const fs::path dir = empty_dir("hbtrack_study_branches");
  const std::string& study = kCoupled;  // its [study]: backbone = {mode = 1, range = [0.01, 6]}, switch = true
  const fs::path out = dir / "out";
  const CliRun r = run_cli("study " + study + " -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "completed");
  EXPECT_TRUE(s["failed_checks"].empty());

  // The backbone: its own folder, finished, from the in-phase linear mode (omega = 1: the
  // coupling spring is not stretched) up its hardening.
  ASSERT_EQ(s["backbones"].size(), 1u);
  const json& bb = s["backbones"][0];
  EXPECT_EQ(bb["folder"], "backbone_mode1");
  EXPECT_EQ(read_json(out / "backbone_mode1" / "summary.json")["stop_reason"], "reached_end");
  EXPECT_NEAR(bb["linear_omega"].get<double>(), 1.0, 1e-9);  // K = [[1.05, -0.05], ...]: [1, 1] has eigenvalue 1
  EXPECT_GT(bb["omega_range"][1].get<double>(), 1.0);

  // Every BP of the nominal NFRC is switched or lies on a branch switched before; each switched
  // branch's folder holds a finished result.
  int bps = 0;
  for (const auto& sp : s["nfrc"]["special_points"]) bps += sp["type"] == "BP";
  ASSERT_GE(bps, 1);
  ASSERT_EQ(s["switched"].size(), static_cast<size_t>(bps));
  std::vector<std::string> folders;
  for (const auto& w : s["switched"]) {
    EXPECT_EQ(w["type"], "BP");
    if (w.contains("on_the_branch_of")) {
      EXPECT_NE(std::find(folders.begin(), folders.end(), w["on_the_branch_of"].get<std::string>()), folders.end()) << w;
      continue;
    }
    const std::string folder = w["folder"];
    EXPECT_EQ(folder, "switch_bp" + std::to_string(w["point"].get<int>()));
    EXPECT_EQ(read_json(out / folder / "summary.json")["stop_reason"], "completed") << folder;
    EXPECT_GT(w["points"].get<int>(), 10) << folder;
    folders.push_back(folder);
  }
  ASSERT_FALSE(folders.empty());

  // The page lists every step folder, and the figure it shows was drawn.
  const std::string page = hbtrack::test::file_bytes(out / "index.md");
  EXPECT_NE(page.find("## Backbones and switched branches"), std::string::npos);
  EXPECT_NE(page.find("[backbone_mode1](backbone_mode1/) mode 1"), std::string::npos) << page;
  for (const std::string& f : folders) EXPECT_NE(page.find("[" + f + "](" + f + "/)"), std::string::npos) << f;
  EXPECT_EQ(page.find("## Limit-point tracking"), std::string::npos) << "nothing was tracked";
  const std::vector<std::string> figures = s["figures"].get<std::vector<std::string>>();
  ASSERT_NE(std::find(figures.begin(), figures.end(), "figures/nfrc.png"), figures.end());
  EXPECT_GT(fs::file_size(out / "figures" / "nfrc.png"), 20000u);

  // Resumable: with a switched branch's folder gone and the study marked stopped, --resume runs
  // that step again, keeps the others, and ends with the same summary.
  json stopped = s;
  stopped["stop_reason"] = "interrupted";
  std::ofstream(out / "summary.json") << stopped.dump();
  fs::remove_all(out / folders[0]);
  const CliRun resumed = run_cli("study " + study + " --resume " + out.string());
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("backbone_mode1             done before, kept"), std::string::npos) << resumed.err;
  // Where the study is: the stage of the pipeline, and each step counted as it ends.
  EXPECT_NE(resumed.err.find("study: stage 2 of 8, branches: running " + folders[0]), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("(step 1 of 1)"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("study: stage 8 of 8, figures"), std::string::npos) << resumed.err;
  EXPECT_EQ(without_timing_fields(read_json(out / "summary.json")), without_timing_fields(s));
  fs::remove_all(dir);
}

TEST(StudyBranchesCli, ADuffingStudyRunsItsBackboneAndFindsNoPointToSwitch) {
  // The cheap counterpart of the test above, run under the sanitizers too (a second of
  // computing in Release): the same stage of the study on the Duffing oscillator, whose NFRC
  // has two folds and no BP or PD.
  const fs::path dir = empty_dir("hbtrack_study_duffing_backbone");
  const std::string duffing = hbtrack::test::file_bytes(hbtrack::test::source_path("examples/duffing.toml"));
  std::ofstream(dir / "case.toml") << duffing
                                   << "\n[study]\nbackbone = { mode = 1, range = [0.01, 3.0] }\nswitch = true\nsimulate_periods = 0\n";
  const fs::path out = dir / "out";
  const CliRun r = run_cli("study " + (dir / "case.toml").string() + " -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "completed");
  ASSERT_EQ(s["backbones"].size(), 1u);
  EXPECT_EQ(s["backbones"][0]["stop_reason"], "reached_end");
  // x'' + 0.05 x' + x + ...: the linear mode at omega = 1; the EPMC's xi stays c = 0.05 to 1e-8
  // (C = c M is cancelled exactly: tests/test_backbone.cpp), so the largest damping ratio
  // xi / (2 omega) is at the smallest omega, the backbone's start.
  const json& bb = s["backbones"][0];
  EXPECT_NEAR(bb["linear_omega"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(bb["damping_ratio_range"][1].get<double>(), 0.05 / (2 * bb["omega_range"][0].get<double>()), 1e-8);
  EXPECT_TRUE(s["switched"].empty());
  const std::string page = hbtrack::test::file_bytes(out / "index.md");
  EXPECT_NE(page.find("| (the nominal NFRC has no BP or PD) |"), std::string::npos) << page;
  EXPECT_NE(page.find("[backbone_mode1](backbone_mode1/)"), std::string::npos) << page;
  fs::remove_all(dir);
}

TEST(StudyBranchesCli, BadBackboneOrSwitchKeysGiveOneLineErrorsNamingFileFieldAndRule) {
  const fs::path dir = empty_dir("hbtrack_study_branches_bad");
  const struct {
    std::string study, expected;
  } cases[] = {
      {"backbone = { mode = 0, range = [0.01, 2.0] }\n",
       "case.toml:52: study.backbone.mode: must be a linear mode of the model, from 1 to 2, got 0"},
      {"backbone = { mode = 3, range = [0.01, 2.0] }\n", "study.backbone.mode: must be a linear mode of the model, from 1 to 2, got 3"},
      {"backbone = { mode = 1, range = [2.0, 0.01] }\n", "study.backbone.range: expected [lo, hi] modal amplitudes with 0 < lo < hi"},
      {"backbone = { mode = 1, range = [0.0, 1.0] }\n", "study.backbone.range: expected [lo, hi] modal amplitudes with 0 < lo < hi"},
      {"backbone = { mode = 1 }\n", "study.backbone.range: missing (required)"},
      {"backbone = { mode = 1, range = [0.01, 1.0], modes = 2 }\n", "study.backbone.modes: unknown key (did you mean 'mode'?)"},
      {"backbone = [{ mode = 1, range = [0.01, 1.0] }, { mode = 1, range = [0.1, 1.0] }]\n",
       "study.backbone[1].mode: mode 1 appears twice"},
      {"backbone = 1\n", "study.backbone: expected a table {mode = K, range = [lo, hi]} (or an array of them)"},
      {"switch = \"yes\"\n", "study.switch: expected true or false"},
      {"switched = true\n", "study.switched: unknown key (did you mean 'switch'?)"},
      {"switch = false\n", "study.track: missing"},
  };
  for (const auto& c : cases) {
    const std::string study = write_case(dir, c.study).string();
    const CliRun r = run_cli("study " + study + " -o " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << c.study << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.study << r.err;
    EXPECT_NE(r.err.find("case.toml"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_study_branches_cli
