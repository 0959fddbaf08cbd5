// The command line on the inputs and events of issue 24 ("Reliability, round 2"): deep nesting,
// endless input streams, huge sweeps, a full disk, and a sweep restarted while the tasks of the
// killed one still run.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_limits_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::count_lines;
using hbtrack::test::run_cli;

namespace {

fs::path fresh_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir("hbtrack_limits_" + name, false); }

std::string duffing() { return hbtrack::test::source_path("examples/duffing.toml"); }

// True while a process holds the result-folder lock of DIR (an open-file-description lock).
bool folder_in_use(const fs::path& dir) {
  const int fd = ::open((dir / ".hbtrack.lock").c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct flock l {};
  l.l_type = F_WRLCK;
  l.l_whence = SEEK_SET;
  const bool held = ::fcntl(fd, F_OFD_GETLK, &l) == 0 && l.l_type != F_UNLCK;
  ::close(fd);
  return held;
}

// Polls `ready` every 20 ms for up to `seconds`.
template <class F>
bool wait_until(F ready, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return ready();
}

}  // namespace

// Exit 139 before: the TOML parser recursed once per bracket.
TEST(LimitsCli, DeepBracketsAreBadInputNotACrash) {
  const fs::path dir = fresh_dir("deep");
  fs::create_directories(dir);
  const fs::path deep = dir / "deep.toml";
  std::ofstream(deep) << "x=" << std::string(8000, '[');
  const CliRun file = run_cli("frc " + deep.string() + " -q -o " + (dir / "out").string());
  EXPECT_EQ(file.exit_code, 2) << file.err;
  EXPECT_NE(file.err.find("nested deeper than 64"), std::string::npos) << file.err;
  const CliRun set =
      run_cli("frc " + duffing() + " -q -o " + (dir / "out").string() + " --set 'amplitude=" + std::string(20000, '[') + "'");
  EXPECT_EQ(set.exit_code, 2) << set.err;
}

// /dev/zero was read until memory ran out.
TEST(LimitsCli, CaseThatIsNotARegularFileIsBadInput) {
  const CliRun run = run_cli("frc /dev/zero -q -o " + fresh_dir("zero").string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("/dev/zero: is not a regular file"), std::string::npos) << run.err;
}

// 1:2:100000000 allocated until the machine ran out of memory; 2 000 000 made as many folders.
TEST(LimitsCli, SweepOfMoreTasksThanTheLimitIsRefusedBeforeAnyFolder) {
  for (const std::string count : {"100000000", "2000000"}) {
    const fs::path dir = fresh_dir("huge_sweep");
    const CliRun run = run_cli("sweep " + duffing() + " -q --param amplitude --values 1:2:" + count + " -o " + dir.string());
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find(count + " tasks, more than the 100000 one sweep runs"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir)) << "nothing is written for a refused sweep";
  }
  const fs::path dir = fresh_dir("huge_product");
  const CliRun product =
      run_cli("sweep " + duffing() + " -q --param amplitude --values 1:2:1000 --param amplitude --values 1:2:1000 -o " + dir.string());
  EXPECT_EQ(product.exit_code, 2) << product.err;
  EXPECT_NE(product.err.find("1000000 tasks"), std::string::npos) << product.err;
}

// On a full disk summary.json ended up empty and --resume refused the folder. A file-size limit
// (ulimit -f, in 512-byte blocks under sh; SIGXFSZ ignored so that writes fail with EFBIG as
// they do with ENOSPC) stands for the full disk.
TEST(LimitsCli, FullDiskIsReportedAndLeavesNoEmptySummary) {
  const fs::path dir = fresh_dir("full_disk");
  // No `trap '' XFSZ`: the limit as a user sets it (hbtrack ignores SIGXFSZ; it died of it, exit 153).
  const std::string command =
      "sh -c \"ulimit -f 2; exec " + std::string(HBTRACK_CLI) + " frc " + duffing() + " -q -o " + dir.string() + "\"";
  const int status = std::system((command + " 2> " + (dir.string() + ".err")).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  std::stringstream err;
  err << std::ifstream(dir.string() + ".err").rdbuf();
  EXPECT_EQ(WEXITSTATUS(status), 3) << err.str();
  EXPECT_NE(err.str().find("write failed"), std::string::npos) << err.str();
  // The first summary.json may not fit either; if one was renamed into place it is whole.
  if (fs::exists(dir / "summary.json")) {
    EXPECT_GT(fs::file_size(dir / "summary.json"), 0u);
    const nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir / "summary.json"), nullptr, false);
    EXPECT_FALSE(summary.is_discarded()) << "summary.json is not whole JSON";
  }
  EXPECT_FALSE(fs::exists(dir / "summary.json.tmp"));
}

// A sweep killed with SIGKILL leaves its tasks running. Rerun at once, it started them again
// into the same folders (two writers: branch.csv cut short under a summary of 5000 points, and
// exit 0). Now the rerun leaves a task that another run still computes alone, and says so; once
// the orphans are done, a rerun accepts their complete results.
TEST(LimitsCli, RestartedSweepLeavesLiveOrphanTasksAlone) {
  const fs::path dir = fresh_dir("orphans");
  // About 1500 points per task (a second or two): long enough to be caught running.
  const std::vector<std::string> args{"sweep",
                                      duffing(),
                                      "-q",
                                      "--jobs",
                                      "2",
                                      "--param",
                                      "amplitude",
                                      "--values",
                                      "0.9,1.0",
                                      "--set",
                                      "continuation.step=0.003",
                                      "--set",
                                      "continuation.step_max=0.003",
                                      "-o",
                                      dir.string()};
  const pid_t sweep = hbtrack::test::spawn_cli(args);
  ASSERT_GT(sweep, 0);
  const fs::path tasks[] = {dir / "tasks" / "0000", dir / "tasks" / "0001"};
  const bool running =
      wait_until([&] { return count_lines(tasks[0] / "branch.csv") > 20 && count_lines(tasks[1] / "branch.csv") > 20; }, 60);
  kill(sweep, SIGKILL);  // the parent only: its tasks go on as orphans
  EXPECT_EQ(hbtrack::test::wait_for_exit(sweep), -1);
  ASSERT_TRUE(running) << "the tasks never started";
  ASSERT_TRUE(folder_in_use(tasks[0]) || folder_in_use(tasks[1]))
      << "the orphans finished before the rerun could start (machine too slow?)";

  std::string command;
  for (size_t i = 1; i < args.size(); ++i) command += " '" + args[i] + "'";
  const CliRun rerun = run_cli(args[0] + command);
  EXPECT_EQ(rerun.exit_code, 1) << "a live task must not count as done: " << rerun.err;
  EXPECT_NE(rerun.err.find("still being computed by pid"), std::string::npos) << rerun.err;

  ASSERT_TRUE(wait_until([&] { return !folder_in_use(tasks[0]) && !folder_in_use(tasks[1]); }, 120));
  const CliRun after = run_cli(args[0] + command);
  EXPECT_EQ(after.exit_code, 0) << after.err;
  for (const fs::path& task : tasks) {
    const nlohmann::json summary = nlohmann::json::parse(std::ifstream(task / "summary.json"));
    EXPECT_EQ(count_lines(task / "branch.csv"), 1 + summary["points"].get<int>()) << task;
  }
}

// A second run into the folder of a live one is refused (it would write the same files).
TEST(LimitsCli, SecondRunIntoALiveFolderIsRefused) {
  const fs::path dir = fresh_dir("busy");
  const pid_t first = hbtrack::test::spawn_cli(
      {"frc", duffing(), "-q", "--set", "continuation.step=0.003", "--set", "continuation.step_max=0.003", "-o", dir.string()});
  ASSERT_GT(first, 0);
  const bool started = wait_until([&] { return folder_in_use(dir); }, 60);
  const CliRun second = run_cli("frc " + duffing() + " -q -o " + dir.string());
  const int first_exit = hbtrack::test::wait_for_exit(first);
  ASSERT_TRUE(started);
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("is being written by another hbtrack run (pid " + std::to_string(first) + ")"), std::string::npos)
      << second.err;
  EXPECT_EQ(first_exit, 0);
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir / "summary.json"));
  EXPECT_EQ(count_lines(dir / "branch.csv"), 1 + summary["points"].get<int>());
}

// On a full disk `continue` (and `switch`, the same path) left a partial last row, after which
// the folder could not be read or exported, and exited 1 as if the continuation had failed.
// Every limit from 2 to 9 blocks (1 to 4.5 KB) cuts somewhere else: each must leave whole rows.
TEST(LimitsCli, ContinueOnAFullDiskLeavesWholeRowsAndExits3) {
  for (int blocks = 2; blocks <= 9; ++blocks) {
    const fs::path dir = fresh_dir("continue_full_" + std::to_string(blocks));
    const std::string command = "sh -c \"ulimit -f " + std::to_string(blocks) + "; exec " + std::string(HBTRACK_CLI) + " continue " +
                                duffing() + " --param amplitude --omega 1.2 --range 0.05:3 -q -o " + dir.string() + "\" 2> " +
                                dir.string() + ".err";
    const int status = std::system(command.c_str());
    std::stringstream err;
    err << std::ifstream(dir.string() + ".err").rdbuf();
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3) << blocks << " blocks: " << err.str();
    EXPECT_NE(err.str().find("write failed"), std::string::npos) << err.str();
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() != ".csv") continue;
      const std::string bytes = hbtrack::test::file_bytes(entry.path());
      if (bytes.empty()) continue;
      EXPECT_EQ(bytes.back(), '\n') << entry.path() << " ends in a partial row (" << blocks << " blocks)";
      const auto columns = hbtrack::test::csv_header(entry.path()).size();
      std::stringstream rows(bytes);
      for (std::string line; std::getline(rows, line);)
        EXPECT_EQ(static_cast<size_t>(std::count(line.begin(), line.end(), ',')) + 1, columns) << entry.path() << ": " << line;
    }
  }
}

}  // namespace hbtrack_tests::file_limits_cli
