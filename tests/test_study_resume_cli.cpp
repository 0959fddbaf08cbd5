// `hbtrack study --resume DIR` (issue 24: an interrupted study left `stop_reason: running` and
// could not resume) and one study per folder (a second study into a live one's folder crashed on
// a null JSON value after an exit-3 step).
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_resume_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;
using nlohmann::json;

namespace {

fs::path fresh_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir(name, true); }

// A study of seconds: the Duffing oscillator's limit points tracked in the amplitude, with a
// validation NFRC at 2.5 and none of the optional steps (simulation, convergence).
fs::path write_small_study(const fs::path& dir) {
  std::ifstream duffing(hbtrack::test::source_path("examples/duffing.toml"));
  std::ofstream out(dir / "case.toml");
  out << duffing.rdbuf() << "\n[study]\ntrack = [ { parameter = \"amplitude\", range = [0.5, 3.0], validate = [2.5] } ]\nmax_points = 40\n"
      << "simulate_periods = 0\n";
  return dir / "case.toml";
}

using hbtrack::test::read_json;

// A summary without what differs between two runs of the same study: times, and what the resumed
// run says about itself.
json without_timings(json j) {
  if (j.is_object()) {
    for (const char* key : {"wall_s", "timings", "resumed_steps", "jobs", "runner"}) j.erase(key);
    for (auto& [key, value] : j.items()) value = without_timings(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_timings(value);
  }
  return j;
}

// index.md with its times (one decimal, "%.1f") masked.
std::string page_without_timings(const fs::path& p) {
  return std::regex_replace(hbtrack::test::file_bytes(p), std::regex(R"(\b[0-9]+\.[0-9] s\b|\| [0-9]+\.[0-9] \|)"), "T");
}

// Polls DIR/summary.json until its steps list has an entry (the nominal NFRC ended).
bool wait_for_first_step(const fs::path& summary, pid_t pid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    try {
      if (fs::exists(summary) && !read_json(summary)["steps"].empty()) return true;
    } catch (const std::exception&) {
    }
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace

TEST(StudyResume, AStudyKilledAfterItsFirstStepResumesToTheSamePageKeepingThatStep) {
  const fs::path dir = fresh_dir("hbtrack_study_resume");
  const std::string study = write_small_study(dir).string();
  const CliRun full = run_cli("study " + study + " -q --jobs 1 -o " + (dir / "full").string());
  ASSERT_TRUE(full.exit_code == 0 || full.exit_code == 1) << full.err;

  // Killed outright (SIGKILL, with its children) once the nominal NFRC ended: nothing can say
  // "interrupted", the summary is left at `running`.
  const fs::path part = dir / "part";
  const pid_t pid = hbtrack::test::spawn_cli({"study", study, "-q", "--jobs", "1", "-o", part.string()}, true);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for_first_step(part / "summary.json", pid));
  ::kill(-pid, SIGKILL);
  hbtrack::test::wait_for_exit(pid);
  const json killed = read_json(part / "summary.json");
  ASSERT_EQ(killed["stop_reason"], "running");
  const std::string nfrc_branch = hbtrack::test::file_bytes(part / "nfrc" / "branch.csv");

  const CliRun resumed = run_cli("study " + study + " --jobs 1 --resume " + part.string());
  EXPECT_EQ(resumed.exit_code, full.exit_code) << resumed.err;
  EXPECT_NE(resumed.err.find("nfrc"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("done before, kept"), std::string::npos) << resumed.err;
  const json s = read_json(part / "summary.json");
  EXPECT_GE(s["resumed_steps"].get<int>(), 1);
  EXPECT_EQ(hbtrack::test::file_bytes(part / "nfrc" / "branch.csv"), nfrc_branch);  // kept, not recomputed
  EXPECT_EQ(without_timings(s), without_timings(read_json(dir / "full" / "summary.json")));
  EXPECT_EQ(page_without_timings(part / "index.md"), page_without_timings(dir / "full" / "index.md"));

  // A finished study, or other settings, are refused in one line.
  const CliRun again = run_cli("study " + study + " --resume " + part.string());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("finished ("), std::string::npos) << again.err;
  json stopped = s;
  stopped["stop_reason"] = "interrupted";
  std::ofstream(part / "summary.json") << stopped.dump();
  const CliRun other = run_cli("study " + study + " --set amplitude=1.5 --resume " + part.string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("other settings"), std::string::npos) << other.err;
  const CliRun not_a_study = run_cli("study " + study + " --resume " + (part / "nfrc").string());
  EXPECT_EQ(not_a_study.exit_code, 2);
  EXPECT_NE(not_a_study.err.find("not a study"), std::string::npos) << not_a_study.err;
  // A step folder a live process still writes (a step orphaned by a study killed without its
  // children): resuming would run the step again beside it.
  const pid_t orphan =
      hbtrack::test::spawn_cli({"frc", study, "-q", "--set", "continuation.step=0.0005", "--set", "continuation.step_max=0.0005", "--set",
                                "continuation.max_points=100000", "-o", (part / "nfrc").string()});
  ASSERT_GT(orphan, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  // Until it holds the folder's lock (its pid in the lock file; branch.csv is already there).
  while (hbtrack::test::file_bytes(part / "nfrc" / ".hbtrack.lock") != std::to_string(orphan) + "\n" &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const CliRun live = run_cli("study " + study + " --resume " + part.string());
  ::kill(orphan, SIGKILL);
  hbtrack::test::wait_for_exit(orphan);
  EXPECT_EQ(live.exit_code, 2);
  EXPECT_NE(live.err.find("nfrc is still being written by another process (pid " + std::to_string(orphan) + ")"), std::string::npos)
      << live.err;
  for (const CliRun& r : {again, other, not_a_study, live}) EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  fs::remove_all(dir);
}

TEST(StudyResume, CtrlCStopsTheStudyAsInterrupted) {
  const fs::path dir = fresh_dir("hbtrack_study_interrupt");
  const std::string study = write_small_study(dir).string();
  const fs::path out = dir / "out";
  const pid_t pid = hbtrack::test::spawn_cli({"study", study, "-q", "--jobs", "1", "-o", out.string()}, true);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for_first_step(out / "summary.json", pid));
  ::kill(-pid, SIGINT);  // Ctrl-C: the study and its running step
  EXPECT_EQ(hbtrack::test::wait_for_exit(pid), 1);
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "interrupted");
  EXPECT_TRUE(fs::exists(out / "index.md"));  // resuming is the test above
  fs::remove_all(dir);
}

TEST(StudyResume, ASecondStudyIntoALiveStudysFolderIsRefusedInOneLine) {
  const fs::path dir = fresh_dir("hbtrack_study_two");
  const std::string study = write_small_study(dir).string();
  const fs::path out = dir / "out";
  const pid_t pid = hbtrack::test::spawn_cli({"study", study, "-q", "--jobs", "1", "-o", out.string()}, true);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for_first_step(out / "summary.json", pid));
  const CliRun second = run_cli("study " + study + " -q -o " + out.string());
  const CliRun resume = run_cli("study " + study + " -q --resume " + out.string());
  ::kill(-pid, SIGKILL);
  hbtrack::test::wait_for_exit(pid);
  for (const CliRun& r : {second, resume}) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("is being written by another hbtrack run"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  fs::remove_all(dir);
}

TEST(StudyResume, AFailedNominalStepStopsTheStudyWithItsReasonAndResumeRunsItAgain) {
  // nfrc/summary.json a folder: the nominal step cannot write its summary (exit 3). The study
  // then ended with "[json.exception.type_error.306] cannot use value() with null", exit 3.
  const fs::path dir = fresh_dir("hbtrack_study_failed_step");
  const std::string study = write_small_study(dir).string();
  const fs::path out = dir / "out";
  fs::create_directories(out / "nfrc" / "summary.json");
  const CliRun failed = run_cli("study " + study + " -q --jobs 1 -o " + out.string());
  EXPECT_EQ(failed.exit_code, 1) << failed.err;
  EXPECT_NE(failed.err.find("study stopped: nfrc failed (exit 3"), std::string::npos) << failed.err;
  EXPECT_EQ(failed.err.find("json.exception"), std::string::npos) << failed.err;
  // The reason, then the command that goes on: the one typed, -o replaced by --resume.
  EXPECT_EQ(std::count(failed.err.begin(), failed.err.end(), '\n'), 2) << failed.err;
  EXPECT_NE(failed.err.find("\nstudy stopped: resume with: " + std::string(HBTRACK_CLI) + " study " + study + " -q --jobs 1 --resume " +
                            out.string() + "\n"),
            std::string::npos)
      << failed.err;
  const json s = read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "nfrc failed (exit 3, see " + out.string() + "/nfrc/log.txt)");
  EXPECT_TRUE(fs::exists(out / "index.md"));
  // The resumed study runs the failed step again from an empty folder (which here removes the cause).
  const CliRun resumed = run_cli("study " + study + " -q --jobs 1 --resume " + out.string());
  EXPECT_TRUE(resumed.exit_code == 0 || resumed.exit_code == 1) << resumed.err;
  const json r = read_json(out / "summary.json");
  EXPECT_EQ(r["resumed_steps"], 0);
  EXPECT_TRUE(r["stop_reason"] == "completed" || r["stop_reason"] == "checks_failed") << r["stop_reason"];
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_study_resume_cli
