// The command printed when Ctrl-C, SIGTERM or --time-limit stop a resumable verb
// (apps/hbtrack/resume_command.hpp): the typed command with --resume DIR in place of -o DIR, and
// running it as printed goes on where the run stopped.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_support.hpp"
#include "resume_command.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_resume_command_cli {

namespace fs = std::filesystem;
using hbtrack::cli::resume_advice;
using hbtrack::cli::resume_command;
using hbtrack::cli::shell_quoted;
using hbtrack::test::CliRun;
using hbtrack::test::count_lines;
using hbtrack::test::file_bytes;
using hbtrack::test::run_cli;

namespace {

nlohmann::json summary_of(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "summary.json")); }

// The line after "resume with: " in a run's stderr, "" when there is none.
std::string printed_resume_command(const std::string& err) {
  const std::string marker = "resume with: ";
  const size_t at = err.find(marker);
  if (at == std::string::npos) return "";
  const size_t start = at + marker.size();
  return err.substr(start, err.find('\n', start) - start);
}

// Runs a printed command as a shell would, stderr returned.
CliRun run_in_shell(const std::string& command) {
  const fs::path err = hbtrack::test::fresh_temp_dir("hbtrack_resume_err");
  const int status = std::system((command + " 2> " + err.string() + " > /dev/null").c_str());
  CliRun r{WEXITSTATUS(status), file_bytes(err)};
  fs::remove(err);
  return r;
}

}  // namespace

TEST(ResumeCommand, ReplacesTheOutputFolderByResumeAndQuotesWhatAShellWouldSplit) {
  const char* typed[] = {"hbtrack", "frc", "case.toml", "-o", "out/a", "--set", "harmonic_balance.harmonics=[1, 3]", "--time-limit", "60"};
  hbtrack::cli::remember_command_line(9, typed);
  EXPECT_EQ(resume_command("out/a"), "hbtrack frc case.toml --set 'harmonic_balance.harmonics=[1, 3]' --time-limit 60 --resume out/a");
  const char* joined[] = {"build/hbtrack", "track", "c.toml", "--output=out/b", "-q"};
  hbtrack::cli::remember_command_line(5, joined);
  EXPECT_EQ(resume_command("out/b"), "build/hbtrack track c.toml -q --resume out/b");
  const char* resumed[] = {"hbtrack", "frc", "c.toml", "--resume", "out/c", "-oout/c"};
  hbtrack::cli::remember_command_line(6, resumed);
  EXPECT_EQ(resume_command("out/c"), "hbtrack frc c.toml --resume out/c") << "an interrupted resume prints itself once";
  EXPECT_EQ(shell_quoted("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quoted(""), "''");
  EXPECT_EQ(resume_advice("time_limit", "X"), "time_limit: resume with: X");
  EXPECT_EQ(resume_advice("newton_failed", "X"), "") << "a rerun would fail the same way";
}

TEST(ResumeCommand, FrcStoppedByItsTimeLimitPrintsACommandThatGoesOn) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_resume_frc");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  // About 4000 points, 0.8 s: stopped part-way by a 0.2 s limit.
  const std::string args =
      "frc " + duffing + " -q --time-limit 0.2 --set continuation.step=0.002 --set continuation.step_max=0.002 -o " + dir.string();
  const CliRun stopped = run_cli(args);
  ASSERT_EQ(stopped.exit_code, 1) << stopped.err;
  ASSERT_EQ(summary_of(dir)["stop_reason"], "time_limit");
  const std::string command = printed_resume_command(stopped.err);
  EXPECT_EQ(command, std::string(HBTRACK_CLI) + " frc " + duffing +
                         " -q --time-limit 0.2 --set continuation.step=0.002 --set continuation.step_max=0.002 --resume " + dir.string())
      << stopped.err;
  EXPECT_NE(stopped.err.find("time_limit: resume with: "), std::string::npos) << stopped.err;
  const int points = summary_of(dir)["points"];
  // As printed, it goes on (and may meet its time limit again).
  const CliRun resumed = run_in_shell(command);
  EXPECT_TRUE(resumed.exit_code == 0 || resumed.exit_code == 1) << resumed.err;
  // The stop saves the state after its last point: the resumed run goes on from there.
  EXPECT_EQ(summary_of(dir)["resumed_at_point"].get<int>(), points);
  EXPECT_GT(summary_of(dir)["points"].get<int>(), points);
  fs::remove_all(dir);
}

TEST(ResumeCommand, TrackStoppedBySigtermPrintsItsResumeCommand) {
  const fs::path root = hbtrack::test::fresh_temp_dir("hbtrack_resume_track", true);
  const std::string nltva = hbtrack::test::source_path("examples/nltva.toml");
  ASSERT_EQ(run_cli("frc " + nltva + " -q -o " + (root / "frc").string()).exit_code, 0);
  // A tenth of the example's step: 532 curve points, half a second; stopped after 50.
  const std::vector<std::string> args{"track",
                                      nltva,
                                      "-q",
                                      "--set",
                                      "continuation.step=0.01",
                                      "--set",
                                      "continuation.step_max=0.01",
                                      "--from",
                                      (root / "frc").string(),
                                      "--lp",
                                      "2",
                                      "--param",
                                      "amplitude",
                                      "--range",
                                      "0.01:0.4",
                                      "-o",
                                      (root / "track").string()};
  const fs::path err = root / "stderr.txt";
  const pid_t pid = hbtrack::test::spawn_cli(args, false, err.string());
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (count_lines(root / "track" / "branch.csv") < 51 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, SIGTERM);
  EXPECT_EQ(hbtrack::test::wait_for_exit(pid), 1);
  ASSERT_EQ(summary_of(root / "track")["stop_reason"], "interrupted") << "the run ended before the signal: make the case slower";
  const std::string text = file_bytes(err);
  EXPECT_NE(text.find("interrupted: resume with: " + std::string(HBTRACK_CLI) + " track " + nltva +
                      " -q --set continuation.step=0.01 --set continuation.step_max=0.01 --from " + (root / "frc").string() +
                      " --lp 2 --param amplitude --range 0.01:0.4 --resume " + (root / "track").string() + "\n"),
            std::string::npos)
      << text;
  const CliRun resumed = run_in_shell(printed_resume_command(text));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(summary_of(root / "track")["stop_reason"], "completed");
  fs::remove_all(root);
}

// A sweep resumes by running the same command again (finished tasks are skipped): stopped by
// SIGTERM to its process group (as Ctrl-C reaches it) after its first task, it prints that
// command, and running it as printed finishes the sweep without recomputing the first task.
TEST(ResumeCommand, SweepStoppedBySigtermPrintsTheSameCommandThatGoesOn) {
  const fs::path root = hbtrack::test::fresh_temp_dir("hbtrack_resume_sweep", true), dir = root / "sweep";
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  // Three NFRCs of about 400 points each, a quarter of a second each, one at a time.
  const std::vector<std::string> args{"sweep",
                                      duffing,
                                      "-q",
                                      "--set",
                                      "continuation.step=0.02",
                                      "--set",
                                      "continuation.step_max=0.02",
                                      "--param",
                                      "amplitude",
                                      "--values",
                                      "0.5,1,2",
                                      "--jobs",
                                      "1",
                                      "-o",
                                      dir.string()};
  const fs::path err = root / "stderr.txt";
  const pid_t pid = hbtrack::test::spawn_cli(args, true, err.string());
  ASSERT_GT(pid, 0);
  const auto first_task_finished = [&] {
    try {
      return summary_of(dir / "tasks" / "0000").value("stop_reason", "running") != "running";
    } catch (const std::exception&) {
      return false;  // not written yet
    }
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!first_task_finished() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(-pid, SIGTERM);
  EXPECT_EQ(hbtrack::test::wait_for_exit(pid), 1);
  ASSERT_EQ(summary_of(dir)["stop_reason"], "interrupted") << "the sweep ended before the signal: make its tasks slower";
  std::string typed = HBTRACK_CLI;
  for (const std::string& a : args) typed += " " + a;
  const std::string text = file_bytes(err);
  EXPECT_NE(text.find("interrupted: resume with: " + typed + "\n"), std::string::npos) << text;
  const CliRun resumed = run_in_shell(printed_resume_command(text));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  const nlohmann::json summary = summary_of(dir);
  EXPECT_EQ(summary["stop_reason"], "completed");
  EXPECT_GE(summary["skipped"].get<int>(), 1) << "the finished first task was computed again";
  EXPECT_EQ(count_lines(dir / "sweep.csv"), 4);
  fs::remove_all(root);
}

}  // namespace hbtrack_tests::file_resume_command_cli
