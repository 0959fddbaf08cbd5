// `hbtrack simulate` end to end: starting from a point of a frc result folder, its result
// contract, and one-line errors for bad flags.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_timeint_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::csv_header;
using hbtrack::test::run_cli;

namespace {

int data_rows(const fs::path& p) {
  std::ifstream in(p);
  int rows = -1;
  for (std::string line; std::getline(in, line);) ++rows;
  return rows;
}

const std::string kDuffing = hbtrack::test::source_path("examples/duffing.toml");

}  // namespace

TEST(TimeIntegrationCli, SimulateFromAFrcPointReachesItsSteadyState) {
  const fs::path hbm = fs::temp_directory_path() / "hbtrack_timeint_cli_frc";
  const fs::path out = fs::temp_directory_path() / "hbtrack_timeint_cli_simulate";
  fs::remove_all(hbm);
  fs::remove_all(out);
  // A smaller forcing than the case's (a parameter the simulation must take over from the
  // result folder's summary.json).
  const CliRun frc = run_cli("frc " + kDuffing + " --set amplitude=0.5 -o " + hbm.string() + " -q");
  ASSERT_EQ(frc.exit_code, 0) << frc.err;
  const int point = 20;
  const CliRun r = run_cli("simulate " + kDuffing + " --from " + hbm.string() + " --point " + std::to_string(point) +
                           " --record-periods 2 -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");

  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["verb"], "simulate");
  EXPECT_TRUE(s["converged"].get<bool>());
  EXPECT_EQ(s["stop_reason"], "converged");
  EXPECT_GT(s["periods"].get<int>(), 0);
  EXPECT_GT(s["timings"]["wall_s"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(s["options"]["parameters"]["amplitude"].get<double>(), 0.5);
  EXPECT_EQ(s["options"]["simulation"]["method"], "newmark");
  EXPECT_EQ(s["options"]["simulation"]["point"], point);
  EXPECT_EQ(s["options"]["simulation"]["steps_per_period"], 256);
  for (const char* key : {"max_x", "min_x", "h1_x", "harmonics_x", "omega", "last_change"}) EXPECT_TRUE(s.contains(key)) << key;
  ASSERT_EQ(s["harmonics_x"].size(), 15u);  // H = 7: a0, a1, b1, ..., a7, b7

  // The HBM point's own omega, and its outputs, as in branch.csv.
  std::ifstream branch(hbm / "branch.csv");
  std::string line;
  for (int i = 0; i <= point + 1; ++i) std::getline(branch, line);
  const double omega = std::stod(line.substr(0, line.find(',')));
  EXPECT_DOUBLE_EQ(s["omega"].get<double>(), omega);
  EXPECT_DOUBLE_EQ(s["start"]["omega"].get<double>(), omega);
  const double hbm_h1 = s["start"]["h1_x"].get<double>();
  EXPECT_NEAR(s["h1_x"].get<double>(), hbm_h1, 5e-3 * hbm_h1);
  const auto& harmonics = s["harmonics_x"];
  EXPECT_DOUBLE_EQ(std::hypot(harmonics[1].get<double>(), harmonics[2].get<double>()), s["h1_x"].get<double>());

  EXPECT_EQ(csv_header(out / "signals.csv"), (std::vector<std::string>{"time", "x"}));
  EXPECT_EQ(data_rows(out / "signals.csv"), 2 * 256);
}

TEST(TimeIntegrationCli, SimulateFromRestWithTheExplicitMethod) {
  const fs::path out = fs::temp_directory_path() / "hbtrack_timeint_cli_rest";
  fs::remove_all(out);
  const CliRun r = run_cli("simulate " + kDuffing + " --omega 0.8 --method dopri5 --steps-per-period 64 -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["options"]["simulation"]["initial_state"], "rest");
  EXPECT_EQ(s["options"]["simulation"]["method"], "dopri5");
  EXPECT_FALSE(s.contains("start"));
  EXPECT_GT(s["force_evaluations"].get<long>(), s["steps"].get<long>());
  EXPECT_EQ(data_rows(out / "signals.csv"), 64);
}

TEST(TimeIntegrationCli, PeriodBudgetRunningOutExitsWithOne) {
  const fs::path out = fs::temp_directory_path() / "hbtrack_timeint_cli_budget";
  fs::remove_all(out);
  const CliRun r = run_cli("simulate " + kDuffing + " --omega 1.0 --max-periods 2 -o " + out.string() + " -q");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no periodic steady state within 2 periods"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_FALSE(s["converged"].get<bool>());
  EXPECT_EQ(s["stop_reason"], "max_periods");
  EXPECT_EQ(s["periods"], 2);
}

TEST(TimeIntegrationCli, BadFlagsFailWithOneLineNamingTheFlag) {
  const std::string out = " -o " + (fs::temp_directory_path() / "hbtrack_timeint_cli_bad").string();
  const std::string folder = (fs::temp_directory_path() / "hbtrack_timeint_cli_nowhere").string();
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--omega 1 --steps-per-period 0", "--steps-per-period: must be an integer >= 1, got '0'"},
      {"--omega 1 --steps-per-period 12", "--steps-per-period: must be >= 2*harmonics+1 = 15"},
      {"--omega 1 --max-periods ten", "--max-periods: must be an integer >= 1, got 'ten'"},
      {"--omega 1 --record-periods -2", "--record-periods: must be an integer >= 1"},
      {"--omega 1 --method rk4", "--method: must be newmark or dopri5, got 'rk4'"},
      {"--omega 1 --element-steps -1", "--element-steps: must be an integer >= 0, got '-1'"},
      {"--omega 1 --method dopri5 --element-steps 32", "--element-steps: only with --method newmark"},
      {"--omega -1", "--omega: must be a number > 0"},
      {"--omega 1.5x", "--omega: must be a number > 0, got '1.5x'"},
      {"", "--omega: required unless --from"},
      {"--point 3", "--point: needs --from"},
      {"--from " + folder, "--from: needs --point"},
      {"--from " + folder + " --point 3", folder + "/summary.json: cannot read"},
  };
  for (const auto& [flags, message] : cases) {
    const CliRun r = run_cli("simulate " + kDuffing + " " + flags + out);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(message), std::string::npos) << flags << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << " -> " << r.err;
  }
}

TEST(TimeIntegrationCli, PointBeyondTheResultIsRejected) {
  const fs::path hbm = fs::temp_directory_path() / "hbtrack_timeint_cli_solve";
  fs::remove_all(hbm);
  const CliRun solve = run_cli("solve " + kDuffing + " --omega 0.7 -o " + hbm.string() + " -q");
  ASSERT_EQ(solve.exit_code, 0) << solve.err;
  const CliRun r = run_cli("simulate " + kDuffing + " --from " + hbm.string() + " --point 1 -o " +
                           (fs::temp_directory_path() / "hbtrack_timeint_cli_beyond").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--point: 1 is beyond the last point"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace hbtrack_tests::file_timeint_cli
