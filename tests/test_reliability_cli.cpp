// Runs that stop before their end keep what they computed and can go on: SIGINT, --time-limit,
// --resume, and the same input gives the same bytes.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_reliability_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::count_lines;
using hbtrack::test::file_bytes;
using hbtrack::test::run_cli;

namespace {

// Per-process folders: ctest runs the tests in parallel processes.
fs::path fresh_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir("hbtrack_reliability_" + name, false); }

std::string duffing() { return hbtrack::test::source_path("examples/duffing.toml"); }

// Duffing with a step at most a tenth of the example's: about 800 points, long enough (half a
// second) to be stopped part-way.
// About 4000 points, 0.8 s on the 2-core machine: long enough to be stopped part-way by a signal
// or a 0.2 s time limit (a run of 800 points took 0.17 s once checkpoints stopped being fsynced
// at every step).
const std::vector<std::string> kSlowDuffing{"--set", "continuation.step=0.002", "--set", "continuation.step_max=0.002"};

nlohmann::json summary_of(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "summary.json")); }

// The result files a resumed run must reproduce exactly (CSV numbers are printed with %.17g, so
// equal bytes mean equal doubles).
void expect_same_results(const fs::path& expected, const fs::path& actual) {
  // stability.csv holds several rows per point: a resumed run keeps them by point index.
  for (const char* file : {"branch.csv", "states.csv", "special_states.csv", "stability.csv"}) {
    EXPECT_FALSE(file_bytes(expected / file).empty()) << file << " missing";
    EXPECT_EQ(file_bytes(expected / file), file_bytes(actual / file)) << file << " differs";
  }
  const nlohmann::json a = summary_of(expected), b = summary_of(actual);
  EXPECT_EQ(a["points"], b["points"]);
  EXPECT_EQ(a["stop_reason"], b["stop_reason"]);
  EXPECT_EQ(a["special_points"], b["special_points"]);
  EXPECT_EQ(a["newton_iterations"], b["newton_iterations"]);
}

}  // namespace

TEST(Reliability, TwoRunsOfTheSameInputGiveIdenticalBytes) {
  const fs::path first = fresh_dir("first"), second = fresh_dir("second");
  ASSERT_EQ(run_cli("frc " + duffing() + " -q -o " + first.string()).exit_code, 0);
  ASSERT_EQ(run_cli("frc " + duffing() + " -q -o " + second.string()).exit_code, 0);
  ASSERT_GT(count_lines(first / "branch.csv"), 20);
  for (const char* file : {"branch.csv", "states.csv", "special_states.csv", "stability.csv"})
    EXPECT_EQ(file_bytes(first / file), file_bytes(second / file)) << file << " differs";
}

TEST(Reliability, ResumedFrcEqualsTheUninterruptedRun) {
  const fs::path whole = fresh_dir("whole"), parts = fresh_dir("parts");
  ASSERT_EQ(run_cli("frc " + duffing() + " -q -o " + whole.string()).exit_code, 0);
  // Stopped after 15 points, before the first limit point (the branch has about 50): a
  // special point found after the restart must come out as in the whole run.
  const CliRun stopped = run_cli("frc " + duffing() + " -q --set continuation.max_points=15 -o " + parts.string());
  ASSERT_EQ(stopped.exit_code, 0) << stopped.err;
  ASSERT_EQ(summary_of(parts)["stop_reason"], "max_points");
  ASSERT_EQ(count_lines(parts / "branch.csv"), 1 + 15);
  const CliRun resumed = run_cli("frc " + duffing() + " -q --resume " + parts.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(summary_of(parts)["resumed_at_point"], 15);
  // Bit-identical, not merely close: the checkpoint restores every double the next step reads.
  expect_same_results(whole, parts);
}

TEST(Reliability, ResumeRefusesOtherSettingsAndFinishedRuns) {
  const fs::path dir = fresh_dir("refuse");
  ASSERT_EQ(run_cli("frc " + duffing() + " -q --set continuation.max_points=5 -o " + dir.string()).exit_code, 0);
  const CliRun other = run_cli("frc " + duffing() + " -q --set amplitude=2 --resume " + dir.string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("checkpoint.json was computed with other settings"), std::string::npos) << other.err;
  EXPECT_EQ(count_lines(dir / "branch.csv"), 1 + 5) << "a refused resume must leave the folder alone";
  // A states.csv shorter than the checkpoint (a folder edited by hand) cannot be continued.
  const std::string states = file_bytes(dir / "states.csv");
  std::ofstream(dir / "states.csv", std::ios::trunc) << states.substr(0, states.find('\n') + 1);
  const CliRun short_states = run_cli("frc " + duffing() + " -q --resume " + dir.string());
  EXPECT_EQ(short_states.exit_code, 2);
  EXPECT_NE(short_states.err.find("states.csv: holds 0 rows, the checkpoint 5"), std::string::npos) << short_states.err;
  std::ofstream(dir / "states.csv", std::ios::trunc) << states;
  ASSERT_EQ(run_cli("frc " + duffing() + " -q --resume " + dir.string()).exit_code, 0);
  const CliRun again = run_cli("frc " + duffing() + " -q --resume " + dir.string());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("finished (reached_end), nothing to resume"), std::string::npos) << again.err;
}

TEST(Reliability, SigintStopsFrcCleanlyAndTheRunResumesToTheSameBranch) {
  const fs::path dir = fresh_dir("sigint"), whole = fresh_dir("sigint_whole");
  std::vector<std::string> args{"frc", duffing(), "-q", "-o", dir.string()};
  args.insert(args.end(), kSlowDuffing.begin(), kSlowDuffing.end());
  const pid_t pid = hbtrack::test::spawn_cli(args);
  ASSERT_GT(pid, 0);
  // Wait for some rows on disk (header + 10), at most 20 s (a loaded CI machine).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (count_lines(dir / "branch.csv") < 11 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  const int exit_code = hbtrack::test::wait_for_exit(pid);
  const nlohmann::json s = summary_of(dir);
  ASSERT_EQ(s["stop_reason"], "interrupted") << "the run ended before the signal: make the case slower";
  EXPECT_EQ(exit_code, 1);
  // Every accepted point is on disk, whole rows only: as many rows as the summary counts.
  EXPECT_EQ(count_lines(dir / "branch.csv"), 1 + s["points"].get<int>());
  EXPECT_EQ(count_lines(dir / "states.csv"), 1 + s["points"].get<int>());
  EXPECT_EQ(file_bytes(dir / "branch.csv").back(), '\n');

  std::string slow;
  for (const std::string& a : kSlowDuffing) slow += " " + a;
  ASSERT_EQ(run_cli("frc " + duffing() + " -q" + slow + " --resume " + dir.string()).exit_code, 0);
  ASSERT_EQ(run_cli("frc " + duffing() + " -q" + slow + " -o " + whole.string()).exit_code, 0);
  expect_same_results(whole, dir);
}

TEST(Reliability, TimeLimitStopsFrcWithItsReason) {
  const fs::path dir = fresh_dir("time_limit");
  std::string slow;
  for (const std::string& a : kSlowDuffing) slow += " " + a;
  const CliRun r = run_cli("frc " + duffing() + " -q --time-limit 0.2" + slow + " -o " + dir.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("continuation stopped: time_limit"), std::string::npos) << r.err;
  const nlohmann::json s = summary_of(dir);
  EXPECT_EQ(s["stop_reason"], "time_limit");
  EXPECT_GE(s["points"].get<int>(), 1);
  EXPECT_EQ(count_lines(dir / "branch.csv"), 1 + s["points"].get<int>());
}

namespace {

// `track` on the absorber (examples/nltva.toml) at a tenth of its step: 532 curve points, the
// first leg (towards small amplitudes) 190 of them with the minimum that gives birth to the
// isola at point 42, the second a maximum (239) and a minimum (348). Half a second in Release.
std::vector<std::string> nltva_track_args(const std::string& from) {
  return {"track",
          hbtrack::test::source_path("examples/nltva.toml"),
          "-q",
          "--set",
          "continuation.step=0.01",
          "--set",
          "continuation.step_max=0.01",
          "--from",
          from,
          "--lp",
          "2",
          "--param",
          "amplitude",
          "--range",
          "0.01:0.4"};
}

// Runs `args -o dir`, sends SIGINT once `rows` curve points are on disk, returns the exit code.
int track_interrupted_after(std::vector<std::string> args, const fs::path& dir, int rows) {
  args.insert(args.end(), {"-o", dir.string()});
  const pid_t pid = hbtrack::test::spawn_cli(args);
  if (pid <= 0) return -1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (count_lines(dir / "branch.csv") < 1 + rows && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, SIGINT);
  return hbtrack::test::wait_for_exit(pid);
}

std::string command_line(const std::vector<std::string>& args) {
  std::string line;
  for (const std::string& a : args) line += (line.empty() ? "" : " ") + a;
  return line;
}

}  // namespace

// Stopped in the first leg (after its extremum was detected, before the leg ended and typed it)
// and in the second (after the first leg's extremum and one of its own): the resumed curve, its
// extrema and their types equal the uninterrupted run's, byte for byte.
TEST(Reliability, InterruptedTrackResumesToTheSameCurveInEitherLeg) {
  const fs::path root = fresh_dir("track");
  const std::string frc = (root / "frc").string();
  ASSERT_EQ(run_cli("frc " + hbtrack::test::source_path("examples/nltva.toml") + " -q -o " + frc).exit_code, 0);
  const std::vector<std::string> args = nltva_track_args(frc);
  const fs::path whole = root / "whole";
  ASSERT_EQ(run_cli(command_line(args) + " -o " + whole.string()).exit_code, 0);
  const nlohmann::json w = summary_of(whole);
  ASSERT_EQ(w["legs"][0]["points"], 191) << "the case changed: pick new stopping points";
  ASSERT_EQ(w["special_points"].size(), 3u);

  for (const int rows : {100, 300}) {
    const fs::path dir = root / ("stopped_at_" + std::to_string(rows));
    EXPECT_EQ(track_interrupted_after(args, dir, rows), 1);
    const nlohmann::json s = summary_of(dir);
    ASSERT_EQ(s["stop_reason"], "interrupted") << "the run ended before the signal: make the case slower";
    EXPECT_EQ(count_lines(dir / "branch.csv"), 1 + s["points"].get<int>());
    // --resume takes --from, --lp, --param, --range and --method from the stopped run.
    const std::string resume = "track " + hbtrack::test::source_path("examples/nltva.toml") +
                               " -q --set continuation.step=0.01 --set continuation.step_max=0.01 --resume " + dir.string();
    const CliRun resumed = run_cli(resume);
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    // The checkpoint is written between steps: the point whose observer saw the stop is on disk
    // but after the last checkpoint, so the resumed run recomputes it (and drops the row first).
    const int resumed_at = summary_of(dir)["resumed_at_point"];
    EXPECT_GE(resumed_at, s["points"].get<int>() - 1);
    EXPECT_LE(resumed_at, s["points"].get<int>());
    for (const char* file : {"branch.csv", "states.csv"}) EXPECT_EQ(file_bytes(whole / file), file_bytes(dir / file)) << file << " differs";
    const nlohmann::json r = summary_of(dir);
    for (const char* key : {"points", "stop_reason", "special_points", "newton_iterations", "jacobian_evaluations"})
      EXPECT_EQ(r[key], w[key]) << key;
    // Finished now: a second resume is refused, as is one with other settings.
    const CliRun again = run_cli(resume);
    EXPECT_EQ(again.exit_code, 2);
    EXPECT_NE(again.err.find("finished (completed), nothing to resume"), std::string::npos) << again.err;
  }
  const fs::path other = root / "other";
  ASSERT_EQ(track_interrupted_after(args, other, 100), 1);
  const CliRun extended = run_cli(command_line(args) + " --method extended --resume " + other.string());
  EXPECT_EQ(extended.exit_code, 2);
  EXPECT_NE(extended.err.find("checkpoint.json was computed with other settings"), std::string::npos) << extended.err;
  // A run written when --lp counted in the NFRC's order (no lp_order) is not resumed: its --lp may
  // name another limit point now.
  nlohmann::json before_lp_order = summary_of(other);
  before_lp_order["options"]["tracking"].erase("lp_order");
  std::ofstream(other / "summary.json") << before_lp_order.dump();
  const CliRun old_order = run_cli(command_line(args) + " --resume " + other.string());
  EXPECT_EQ(old_order.exit_code, 2);
  EXPECT_NE(old_order.err.find("options.tracking.lp_order missing"), std::string::npos) << old_order.err;
  const CliRun no_from = run_cli("track " + hbtrack::test::source_path("examples/nltva.toml") + " -q --lp 1 -o " + other.string());
  EXPECT_EQ(no_from.exit_code, 2);
  EXPECT_NE(no_from.err.find("--from is required (or --resume DIR)"), std::string::npos) << no_from.err;
}

}  // namespace hbtrack_tests::file_reliability_cli
