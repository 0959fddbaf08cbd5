// --resume goes on only with the model it stopped on, reads its checkpoint bounded, resumes a run
// stopped before its first checkpoint, and keeps the stopped run's counts (issue 39).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_resume_identity_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::file_bytes;
using hbtrack::test::run_cli;

namespace {

fs::path fresh_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir("hbtrack_resume_identity_" + name); }

nlohmann::json summary_of(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "summary.json")); }

// A copy of examples/duffing.toml with `from` replaced by `to` (the whole text when from is empty).
fs::path duffing_copy(const fs::path& path, const std::string& from = "", const std::string& to = "") {
  std::string text = file_bytes(hbtrack::test::source_path("examples/duffing.toml"));
  if (!from.empty()) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  std::ofstream(path) << text;
  return path;
}

}  // namespace

// An edited stiffness, damping or forcing was resumed silently: the branch mixed two systems.
TEST(ResumeIdentity, AnEditedModelIsRefusedInOneLine) {
  const fs::path dir = fresh_dir("edited"), case_file = fs::path(dir.string() + ".toml");
  for (const auto& [from, to] :
       std::vector<std::pair<std::string, std::string>>{{"K = [[1.0]]", "K = [[1.1]]"},
                                                        {"C = [[0.05]]", "C = [[0.06]]"},
                                                        {"cos = 0.18", "cos = 0.19"},
                                                        {"cubic_stiffness = 0.1", "cubic_stiffness = 0.2"},
                                                        // Outside the base class: resumed before.
                                                        {"cubic_stiffness = 0.1", "cubic_stiffness = 0.1\nweights = [1.5]"}}) {
    fs::remove_all(dir);
    duffing_copy(case_file);
    ASSERT_EQ(run_cli("frc " + case_file.string() + " -q --set continuation.max_points=5 -o " + dir.string()).exit_code, 0);
    duffing_copy(case_file, from, to);
    const std::string branch = file_bytes(dir / "branch.csv");
    const CliRun r = run_cli("frc " + case_file.string() + " -q --resume " + dir.string());
    EXPECT_EQ(r.exit_code, 2) << to << ": " << r.err;
    EXPECT_NE(r.err.find("was computed with another model"), std::string::npos) << to << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(file_bytes(dir / "branch.csv"), branch) << to << ": the refused resume changed branch.csv";
  }
  // The same model in other words (a comment, spacing) still resumes.
  duffing_copy(case_file, "K = [[1.0]]", "K = [[ 1.0 ]]  # unchanged");
  fs::remove_all(dir);
  ASSERT_EQ(run_cli("frc " + case_file.string() + " -q --set continuation.max_points=5 -o " + dir.string()).exit_code, 0);
  duffing_copy(case_file);
  // A few more points: what is tested is that it resumes, not the rest of the NFRC.
  const CliRun same = run_cli("frc " + case_file.string() + " -q --set continuation.max_points=8 --resume " + dir.string());
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(summary_of(dir)["points"], 8);
}

// A law's choice is the element subclass's own state, which the model's hash missed: a case whose
// contact law was changed from polynomial to sqrt resumed the old branch.
TEST(ResumeIdentity, AnotherContactLawIsAnotherModel) {
  const fs::path dir = fresh_dir("law"), case_file = fs::path(dir.string() + ".toml");
  const std::string contact =
      "cubic_stiffness = 0.1\n\n[[elements]]\ntype = \"regularized_contact\"\ndofs = [\"x\"]\n"
      "stiffness = 10.0\ngap = 1.0\nwidth = 0.1\nlaw = ";
  duffing_copy(case_file, "cubic_stiffness = 0.1", contact + "\"polynomial\"");
  fs::remove_all(dir);
  ASSERT_EQ(run_cli("frc " + case_file.string() + " -q --set continuation.max_points=5 -o " + dir.string()).exit_code, 0);
  duffing_copy(case_file, "cubic_stiffness = 0.1", contact + "\"sqrt\"");
  const CliRun r = run_cli("frc " + case_file.string() + " -q --resume " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("was computed with another model"), std::string::npos) << r.err;
  duffing_copy(case_file, "cubic_stiffness = 0.1", contact + "\"polynomial\"");
  // A few more points only: the whole NFRC, shooting-checked on this C0 law, took 3 minutes under
  // the sanitizers.
  const CliRun same = run_cli("frc " + case_file.string() + " -q --set continuation.max_points=8 --resume " + dir.string());
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(summary_of(dir)["points"], 8);
}

// A checkpoint whose settings nest 200 000 deep segfaulted --resume.
TEST(ResumeIdentity, ADeeplyNestedCheckpointIsBadInputNotACrash) {
  const fs::path dir = fresh_dir("deep");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  ASSERT_EQ(run_cli("frc " + duffing + " -q --set continuation.max_points=5 -o " + dir.string()).exit_code, 0);
  std::ofstream(dir / "checkpoint.json") << "{\"format\": 1, \"settings\": " << std::string(200000, '[') << std::string(200000, ']') << "}";
  const CliRun r = run_cli("frc " + duffing + " -q --resume " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("checkpoint.json:1: arrays or objects nested deeper than 64 levels"), std::string::npos) << r.err;
}

// Stopped at its first point (here by a time limit shorter than one point), the run had a
// summary saying time_limit but no checkpoint yet, and --resume refused it.
TEST(ResumeIdentity, ARunStoppedBeforeItsFirstCheckpointResumes) {
  const fs::path whole = fresh_dir("first_whole"), parts = fresh_dir("first_parts");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  ASSERT_EQ(run_cli("frc " + duffing + " -q -o " + whole.string()).exit_code, 0);
  const CliRun stopped = run_cli("frc " + duffing + " -q --time-limit 1e-9 -o " + parts.string());
  ASSERT_EQ(stopped.exit_code, 1) << stopped.err;
  ASSERT_EQ(summary_of(parts)["stop_reason"], "time_limit");
  // The stop saves the state of its first point; a run killed before that save has none, as
  // this folder once its checkpoint is removed.
  ASSERT_TRUE(fs::exists(parts / "checkpoint.json"));
  fs::remove(parts / "checkpoint.json");
  const CliRun resumed = run_cli("frc " + duffing + " -q --resume " + parts.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  for (const char* file : {"branch.csv", "states.csv", "stability.csv"})
    EXPECT_EQ(file_bytes(whole / file), file_bytes(parts / file)) << file;
  // Another case's run is still refused.
  const CliRun other = run_cli("frc " + duffing + " -q --time-limit 1e-9 -o " + (parts.string() + "_2"));
  ASSERT_EQ(other.exit_code, 1);
  const CliRun refused = run_cli("frc " + duffing + " -q --set amplitude=2 --resume " + (parts.string() + "_2"));
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
}

// The summary after a resume counted the stability methods of the new points only.
TEST(ResumeIdentity, TheStabilityMethodCountsCoverTheWholeBranch) {
  const fs::path whole = fresh_dir("methods_whole"), parts = fresh_dir("methods_parts");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  ASSERT_EQ(run_cli("frc " + duffing + " -q -o " + whole.string()).exit_code, 0);
  ASSERT_EQ(run_cli("frc " + duffing + " -q --set continuation.max_points=15 -o " + parts.string()).exit_code, 0);
  ASSERT_EQ(run_cli("frc " + duffing + " -q --resume " + parts.string()).exit_code, 0);
  ASSERT_TRUE(summary_of(whole).contains("stability_methods"));
  EXPECT_EQ(summary_of(whole)["stability_methods"], summary_of(parts)["stability_methods"]);
}

// corners_stepped_over was not in the checkpoint: a resume after the corner reported 0.
TEST(ResumeIdentity, CornersSteppedOverSurviveAResume) {
  const fs::path whole = fresh_dir("corners_whole"), parts = fresh_dir("corners_parts");
  const std::string contact = hbtrack::test::source_path("examples/two_dof_contact.toml") + " -q --set stability.method=none";
  ASSERT_EQ(run_cli("frc " + contact + " -o " + whole.string()).exit_code, 0);
  ASSERT_GE(summary_of(whole)["corners_stepped_over"].get<int>(), 1);
  // The corner is stepped over between points 60 and 100.
  ASSERT_EQ(run_cli("frc " + contact + " --set continuation.max_points=120 -o " + parts.string()).exit_code, 0);
  ASSERT_EQ(run_cli("frc " + contact + " --resume " + parts.string()).exit_code, 0);
  EXPECT_EQ(summary_of(whole)["corners_stepped_over"], summary_of(parts)["corners_stepped_over"]);
  EXPECT_EQ(file_bytes(whole / "branch.csv"), file_bytes(parts / "branch.csv"));
}

// A checkpoint whose state is consistent but of another size reached the engine, which refused it
// after the folder was reopened: exit 3 and the summary left at `running`.
TEST(ResumeIdentity, ACheckpointStateOfAnotherSizeIsBadInput) {
  const fs::path dir = fresh_dir("size");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  ASSERT_EQ(run_cli("frc " + duffing + " -q --set continuation.max_points=5 -o " + dir.string()).exit_code, 0);
  nlohmann::json checkpoint = nlohmann::json::parse(std::ifstream(dir / "checkpoint.json"));
  for (const char* key : {"x", "x_before", "tangent", "unknown_scale"}) checkpoint["state"][key].erase(0);
  std::ofstream(dir / "checkpoint.json") << checkpoint.dump();
  const CliRun r = run_cli("frc " + duffing + " -q --resume " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the state holds 14 unknowns, this case 15"), std::string::npos) << r.err;
  EXPECT_EQ(summary_of(dir)["stop_reason"], "max_points");
}

// The same for `track`: its checkpoint's settings hold the model's hash as frc's do.
TEST(ResumeIdentity, TrackRefusesAnEditedModel) {
  const fs::path root = hbtrack::test::fresh_temp_dir("hbtrack_resume_identity_track", true);
  const fs::path case_file = root / "nltva.toml";
  const std::string original = file_bytes(hbtrack::test::source_path("examples/nltva.toml"));
  std::ofstream(case_file) << original;
  const std::string frc = (root / "frc").string(), dir = (root / "track").string();
  ASSERT_EQ(run_cli("frc " + case_file.string() + " -q -o " + frc).exit_code, 0);
  const std::string track = "track " + case_file.string() + " -q --set continuation.step=0.01 --set continuation.step_max=0.01";
  const CliRun capped =
      run_cli(track + " --set continuation.max_points=20 --from " + frc + " --lp 2 --param amplitude --range 0.01:0.4 -o " + dir);
  ASSERT_EQ(capped.exit_code, 0) << capped.err;
  std::string edited = original;
  const std::string from = "cubic_stiffness = 0.0042";
  ASSERT_NE(edited.find(from), std::string::npos);
  edited.replace(edited.find(from), from.size(), "cubic_stiffness = 0.0043");
  std::ofstream(case_file) << edited;
  const CliRun r = run_cli(track + " --resume " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("was computed with another model"), std::string::npos) << r.err;
  std::ofstream(case_file) << original;
  const CliRun same = run_cli(track + " --resume " + dir);
  EXPECT_EQ(same.exit_code, 0) << same.err;
}

// A `track` checkpoint whose vectors have another size reached the engine (issue 39's leftover):
// now a one-line exit 2 naming the checkpoint and the field, the stopped run's summary unchanged.
TEST(ResumeIdentity, ATrackingCheckpointOfAnotherSizeIsBadInput) {
  const fs::path root = hbtrack::test::fresh_temp_dir("hbtrack_resume_identity_track_size", true);
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  const std::string frc = (root / "frc").string(), dir = (root / "track").string();
  ASSERT_EQ(run_cli("frc " + duffing + " -q -o " + frc).exit_code, 0);
  const std::string track =
      "track " + duffing + " -q --set continuation.max_points=5 --from " + frc + " --lp 1 --param amplitude --range 0.1:2";
  ASSERT_EQ(run_cli(track + " -o " + dir).exit_code, 0);
  const fs::path checkpoint = fs::path(dir) / "checkpoint.json";
  const std::string saved = file_bytes(checkpoint), summary = file_bytes(fs::path(dir) / "summary.json");
  const auto resume_with = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = nlohmann::json::parse(saved);
    edit(j);
    std::ofstream(checkpoint) << j.dump();
    return run_cli(track + " --resume " + dir);
  };
  const CliRun shorter = resume_with([](nlohmann::json& j) {
    for (const char* key : {"x", "x_before", "tangent", "unknown_scale"}) j["state"][key].erase(0);
  });
  EXPECT_EQ(shorter.exit_code, 2) << shorter.err;
  EXPECT_NE(
      shorter.err.find(checkpoint.string() +
                       ": state.x holds 16 values, expected 17 (this case's 15 unknowns, omega and the parameter of a bordered tracking)"),
      std::string::npos)
      << shorter.err;
  EXPECT_EQ(std::count(shorter.err.begin(), shorter.err.end(), '\n'), 1) << shorter.err;
  const CliRun border = resume_with([](nlohmann::json& j) { j["tracking"]["borders"][1].push_back(0.5); });
  EXPECT_EQ(border.exit_code, 2) << border.err;
  EXPECT_NE(border.err.find(checkpoint.string() + ": tracking.borders[1] holds 16 values, expected 15 (this case's unknowns)"),
            std::string::npos)
      << border.err;
  EXPECT_EQ(file_bytes(fs::path(dir) / "summary.json"), summary);
  std::ofstream(checkpoint) << saved;
  EXPECT_EQ(run_cli(track + " --resume " + dir).exit_code, 0);
}

}  // namespace hbtrack_tests::file_resume_identity_cli
