// `hbtrack sweep` end to end on cheap cases: the merged table does not depend on how the tasks
// were spread (one worker, two, MPI ranks), a killed sweep resumes without recomputing what it
// finished, --track follows every limit point, and bad input is refused before anything is written.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_sweep_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::file_bytes;
using hbtrack::test::run_cli;
using nlohmann::json;

namespace {

// Duffing with the cubic stiffness as a second named parameter: NFRCs of about 0.1 s.
const std::string kCase = hbtrack::test::source_path("tests/data/duffing_two_parameters.toml");
const std::string kGrid = "--param amplitude --values 0.8,1.2 --param cubic --values 0.05:0.15:3";

fs::path fresh_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir(name, false); }

std::vector<std::vector<std::string>> csv_rows(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

size_t column(const std::vector<std::vector<std::string>>& rows, const std::string& name) {
  const auto it = std::find(rows.at(0).begin(), rows.at(0).end(), name);
  EXPECT_NE(it, rows[0].end()) << "no column " << name;
  return static_cast<size_t>(it - rows[0].begin());
}

TEST(SweepCli, MergedTableIsTheSameWithOneAndTwoJobs) {
  const fs::path one = fresh_dir("hbtrack_sweep_jobs1"), two = fresh_dir("hbtrack_sweep_jobs2");
  const CliRun r1 = run_cli("sweep " + kCase + " " + kGrid + " --jobs 1 -o " + one.string());
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  // The second run spells the count out (LO:HI:count=N): the same grid, so the same table.
  std::string counted_grid = kGrid;
  counted_grid.replace(counted_grid.find(":3"), 2, ":count=3");
  const CliRun r2 = run_cli("sweep " + kCase + " " + counted_grid + " --jobs 2 -o " + two.string());
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  EXPECT_NE(r2.err.find(" left"), std::string::npos) << "progress with an estimate of the time left: " << r2.err;
  EXPECT_EQ(file_bytes(one / "sweep.csv"), file_bytes(two / "sweep.csv"));

  // One row per task, the first parameter varying slowest; each task ran with its own values.
  const auto rows = csv_rows(one / "sweep.csv");
  ASSERT_EQ(rows.size(), 7u);
  const size_t amplitude = column(rows, "amplitude"), cubic = column(rows, "cubic"), status = column(rows, "status"),
               peak = column(rows, "peak_max_x"), lps = column(rows, "lps");
  const std::vector<std::pair<std::string, std::string>> expected{{"0.8", "0.05"}, {"0.8", "0.1"}, {"0.8", "0.15"},
                                                                  {"1.2", "0.05"}, {"1.2", "0.1"}, {"1.2", "0.15"}};
  for (size_t i = 0; i < expected.size(); ++i) {
    const auto& row = rows[i + 1];
    EXPECT_EQ(row[0], std::to_string(i));
    EXPECT_EQ(row[amplitude], expected[i].first);
    EXPECT_EQ(row[cubic], expected[i].second);
    EXPECT_EQ(row[status], "reached_end") << "task " << i;
    const json s = json::parse(std::ifstream(one / "tasks" / ("000" + std::to_string(i)) / "summary.json"));
    EXPECT_DOUBLE_EQ(s["options"]["parameters"]["cubic"].get<double>(), std::stod(expected[i].second));
    size_t lp_count = 0;
    for (const auto& sp : s["special_points"]) lp_count += sp["type"] == "LP";
    EXPECT_EQ(row[lps], std::to_string(lp_count));
    // More forcing, larger peak, at every stiffness; a stiffer spring, a lower peak (bent further).
    if (i >= 3) {
      EXPECT_GT(std::stod(row[peak]), std::stod(rows[i - 2][peak])) << "task " << i;
    }
    if (i % 3 > 0) {
      EXPECT_LT(std::stod(row[peak]), std::stod(rows[i][peak])) << "task " << i;
    }
  }
  fs::remove_all(one);
  fs::remove_all(two);
}

TEST(SweepCli, MpiRanksGiveTheSameMergedTableAsOneJob) {
#ifndef HBTRACK_MPIEXEC
  GTEST_SKIP() << "hbtrack was built without MPI (install libopenmpi-dev openmpi-bin and reconfigure)";
#else
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "MPI's own allocations are not sanitizer-clean; the Release pass runs this";
  const fs::path one = fresh_dir("hbtrack_sweep_ref"), ranks = fresh_dir("hbtrack_sweep_mpi");
  const CliRun r1 = run_cli("sweep " + kCase + " " + kGrid + " --jobs 1 -q -o " + one.string());
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  // Root in CI containers: Open MPI refuses it unless told; no single-copy shared memory there.
  const std::string command =
      "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none timeout 120 " +
      std::string(HBTRACK_MPIEXEC) + " --oversubscribe -n 3 " + HBTRACK_CLI + " sweep " + kCase + " " + kGrid + " -q -o " + ranks.string() +
      " > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_EQ(file_bytes(one / "sweep.csv"), file_bytes(ranks / "sweep.csv"));
  const json s = json::parse(std::ifstream(ranks / "summary.json"));
  EXPECT_EQ(s["runner"], "3 MPI ranks");
  EXPECT_EQ(s["computed"], 6);
  fs::remove_all(one);
  fs::remove_all(ranks);
#endif
}

TEST(SweepCli, TrackFollowsEveryLimitPointOfEachNfrc) {
  const fs::path dir = fresh_dir("hbtrack_sweep_track");
  const CliRun r = run_cli("sweep " + hbtrack::test::source_path("examples/duffing.toml") +
                           " --param amplitude --values 0.8,1.4 --track amplitude:0.1:2 --jobs 2 -q -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(dir / "sweep.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i][column(rows, "lps")], "2");
    for (const char* curve : {"lp1_track_points", "lp2_track_points"}) EXPECT_GT(std::stoi(rows[i][column(rows, curve)]), 10);
    // Both folds of the Duffing NFRC are born at one cusp (amplitude 0.2996, README): each curve
    // from A = 0.8 or 1.4 passes it once on its way to A = 0.1.
    EXPECT_EQ(rows[i][column(rows, "amplitude_minima")], "2");
    EXPECT_EQ(rows[i][column(rows, "amplitude_maxima")], "0");
  }
  fs::remove_all(dir);
}

TEST(SweepCli, KilledSweepResumesWithoutRecomputingFinishedTasks) {
  const fs::path reference = fresh_dir("hbtrack_sweep_whole"), dir = fresh_dir("hbtrack_sweep_killed");
  const std::string grid = "--param amplitude --values 0.8:1.4:4 --param cubic --values 0.05,0.15";
  const CliRun whole = run_cli("sweep " + kCase + " " + grid + " --jobs 2 -q -o " + reference.string());
  ASSERT_EQ(whole.exit_code, 0) << whole.err;

  std::vector<std::string> args{"sweep", kCase, "--jobs", "1", "-q", "-o", dir.string()};
  for (const char* word : {"--param", "amplitude", "--values", "0.8:1.4:4", "--param", "cubic", "--values", "0.05,0.15"})
    args.push_back(word);
  const pid_t pid = hbtrack::test::spawn_cli(args, true);
  ASSERT_GT(pid, 0);
  // Kill the sweep and the task it is running once three of the eight tasks have finished.
  auto finished_tasks = [&] {
    std::vector<fs::path> done;
    for (int i = 0; i < 8; ++i) {
      const fs::path s = dir / "tasks" / ("000" + std::to_string(i)) / "summary.json";
      if (fs::exists(s) && file_bytes(s).find("\"stop_reason\": \"reached_end\"") != std::string::npos) done.push_back(s);
    }
    return done;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (finished_tasks().size() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(-pid, SIGKILL);
  EXPECT_EQ(hbtrack::test::wait_for_exit(pid), -1);
  const std::vector<fs::path> done = finished_tasks();
  ASSERT_GE(done.size(), 3u);
  ASSERT_LT(done.size(), 8u) << "the sweep ended before it was killed: nothing to resume";
  std::vector<std::pair<fs::file_time_type, std::string>> before;
  for (const fs::path& s : done) before.emplace_back(fs::last_write_time(s), file_bytes(s));

  const CliRun rerun = run_cli("sweep " + kCase + " " + grid + " --jobs 2 -o " + dir.string());
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_NE(rerun.err.find("already finished"), std::string::npos) << rerun.err;
  for (size_t k = 0; k < done.size(); ++k) {
    EXPECT_EQ(fs::last_write_time(done[k]), before[k].first) << done[k] << " was recomputed";
    EXPECT_EQ(file_bytes(done[k]), before[k].second) << done[k];  // holds its own wall time: differs if rerun
  }
  const json s = json::parse(std::ifstream(dir / "summary.json"));
  EXPECT_EQ(s["skipped"].get<size_t>(), done.size());
  EXPECT_EQ(file_bytes(dir / "sweep.csv"), file_bytes(reference / "sweep.csv"));

  // The same folder with other values is refused: its tasks were computed for the old ones.
  const CliRun other =
      run_cli("sweep " + kCase + " --param amplitude --values 0.8:1.4:5 --param cubic --values 0.05,0.15 -o " + dir.string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("holds a sweep with other settings (tasks differs"), std::string::npos) << other.err;
  EXPECT_EQ(std::count(other.err.begin(), other.err.end(), '\n'), 1) << other.err;
  fs::remove_all(reference);
  fs::remove_all(dir);
}

TEST(SweepCli, BadInputGivesOneLineErrorsAndWritesNothing) {
  const fs::path dir = fresh_dir("hbtrack_sweep_bad");
  const fs::path no_header = fs::temp_directory_path() / ("hbtrack_sweep_no_header_" + std::to_string(getpid()) + ".csv");
  const fs::path unknown_column = fs::temp_directory_path() / ("hbtrack_sweep_unknown_column_" + std::to_string(getpid()) + ".csv");
  std::ofstream(no_header) << "0.8,0.05\n1.2,0.15\n";
  std::ofstream(unknown_column) << "amplitude,mu\n0.8,0.1\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--param cubik --values 0.1,0.2", "--param: 'cubik' is not a named parameter"},
      {"--param cubic --values 0.1:0.2", "--values (cubic): expected A,B,... or LO:HI:count=N, got '0.1:0.2'"},
      {"--param cubic --values 0.1:0.2:0", "--values (cubic) COUNT: must be an integer >= 1, got '0'"},
      {"--param cubic --values 0.1:0.2:2.5", "--values (cubic) COUNT: must be an integer >= 1, got '2.5'"},
      {"--param cubic --values 0.1:0.2:count=0", "--values (cubic) COUNT: must be an integer >= 1, got '0'"},
      {"--param cubic --values 0.1:0.2:step=0.01",
       "--values (cubic): the third field of LO:HI:count=N is a number of values, got 'step=0.01'"},
      {"--param cubic --values ''", "--values (cubic): empty list"},
      {"--param cubic --values 0.1,,0.2", "--values (cubic): empty value in the list"},
      {"--param cubic --values 0.1,abc", "--values (cubic): must be a finite number, got 'abc'"},
      {"--param cubic --param amplitude --values 0.1", "--values: one per --param"},
      {"--param cubic --values 0.1 --param cubic --values 0.2", "--param: 'cubic' is given twice"},
      {"--param cubic --values 0.1 --set cubic=0.2", "--param: 'cubic' is swept, it cannot also be given with --set"},
      {"--param cubic --values 0.1 --samples " + no_header.string(), "--samples: give either --samples or --param/--values"},
      {"--samples " + no_header.string(), no_header.string() + ":1: expected a header naming the parameters"},
      {"--samples " + unknown_column.string(), unknown_column.string() + ":1: column 'mu' is not a named parameter"},
      {"--param cubic --values 0.1 --track cubic:0.5:0.9", "--track: the range 0.5:0.9 must contain cubic of every task"},
      {"--param cubic --values 0.1 --track cubic:0.5", "--track: expected PARAM or PARAM:LO:HI, got 'cubic:0.5'"},
      {"--param cubic --values 0.1 --track cubic", "--track: give PARAM:LO:HI, the case's [study] section has no range for 'cubic'"},
      {"--param cubic --values 0.1 --jobs -1", "--jobs: must be >= 0"},
  };
  for (const auto& [args, message] : cases) {
    const CliRun r = run_cli("sweep " + kCase + " " + args + " -o " + dir.string());
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir)) << args << " wrote " << dir;
  }
  fs::remove(no_header);
  fs::remove(unknown_column);
}

}  // namespace

}  // namespace hbtrack_tests::file_sweep_cli
