// The command-line tool end to end: output contracts, exit codes, one-line errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::csv_header;
using hbtrack::test::run_cli;

namespace {}  // namespace

TEST(Cli, FrcOnDuffingWritesTheContractedResults) {
  const fs::path out = fs::temp_directory_path() / "hbtrack_cli_duffing";
  fs::remove_all(out);
  const CliRun r = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["stop_reason"], "reached_end");
  EXPECT_GT(s["points"].get<int>(), 20);
  EXPECT_GT(s["newton_iterations"].get<int>(), 0);
  EXPECT_EQ(s["failed_steps"].get<int>(), 0);
  EXPECT_GT(s["timings"]["wall_s"].get<double>(), 0.0);
  ASSERT_EQ(s["special_points"].size(), 2u);
  int rows = -1;
  {
    std::ifstream in(out / "branch.csv");
    for (std::string line; std::getline(in, line);) ++rows;
  }
  for (const auto& sp : s["special_points"]) {
    EXPECT_EQ(sp["type"], "LP");
    EXPECT_TRUE(sp.contains("omega"));
    EXPECT_TRUE(sp.contains("max_x"));
    EXPECT_TRUE(sp["parameters"].contains("amplitude"));
    EXPECT_LT(sp["index"].get<int>(), rows);
  }
  EXPECT_EQ(rows, s["points"].get<int>());
  // The historical columns first (the harmonics' columns follow: test_result_columns_cli.cpp).
  const std::vector<std::string> header = csv_header(out / "branch.csv");
  ASSERT_GE(header.size(), 5u);
  EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 5),
            (std::vector<std::string>{"omega", "stable", "max_x", "min_x", "h1_x"}));
}

TEST(Cli, SolveAndSetOverride) {
  const fs::path out = fs::temp_directory_path() / "hbtrack_cli_solve";
  fs::remove_all(out);
  const CliRun r = run_cli("solve " + hbtrack::test::source_path("examples/duffing.toml") + " --omega 0.5 --set amplitude=0.5 -o " +
                           out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_TRUE(s["converged"].get<bool>());
  EXPECT_DOUBLE_EQ(s["options"]["parameters"]["amplitude"].get<double>(), 0.5);
  // Far below resonance at half the force the response is nearly linear: 0.09 / |1 - w^2 + i c w|
  // = 0.1199; the cubic term shifts it by about 3/4 k3 a^2 / (1 - w^2) = 0.14 %, so 0.5 % bounds it.
  const double linear = 0.09 / std::hypot(1.0 - 0.25, 0.05 * 0.5);
  EXPECT_NEAR(s["h1_x"].get<double>(), linear, 0.005 * linear);
}

TEST(Cli, BadInputFailsWithOneLineReason) {
  const fs::path bad = fs::temp_directory_path() / "hbtrack_cli_bad.toml";
  std::ofstream(bad) << "[model]\ndofs = [\"x\"]\nM = [[1.0]]\n";
  const fs::path bad_out = fs::temp_directory_path() / "hbtrack_cli_bad_out";
  fs::remove_all(bad_out);
  const CliRun r = run_cli("frc " + bad.string() + " -o " + bad_out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("model.K: missing"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  // Input is checked before the output folder is made: nothing that looks like a result.
  EXPECT_FALSE(fs::exists(bad_out));

  const CliRun missing = run_cli("frc /nonexistent/case.toml -o /tmp/x");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find("/nonexistent/case.toml: file does not exist"), std::string::npos) << missing.err;

  const CliRun unknown_param = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " --set mu=0.1 -o /tmp/x");
  EXPECT_NE(unknown_param.exit_code, 0);
  EXPECT_NE(unknown_param.err.find("--set mu: unknown parameter"), std::string::npos) << unknown_param.err;

  // Command-line parse errors follow the same contract: one line naming the flag, exit 2.
  const CliRun unknown_flag = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " --omega-end 3 -o /tmp/x");
  EXPECT_EQ(unknown_flag.exit_code, 2);
  EXPECT_NE(unknown_flag.err.find("--omega-end"), std::string::npos) << unknown_flag.err;
  EXPECT_EQ(std::count(unknown_flag.err.begin(), unknown_flag.err.end(), '\n'), 1) << unknown_flag.err;
  const CliRun no_output = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml"));
  EXPECT_EQ(no_output.exit_code, 2);
  EXPECT_NE(no_output.err.find("--output is required"), std::string::npos) << no_output.err;
}

TEST(Cli, BadExcitationExitsWithTwoAndOneLineNamingTheFileAndField) {
  // The two examples with one line broken each: exit 2, "hbtrack: FILE:LINE: FIELD: RULE".
  struct Broken {
    const char *example, *from, *to, *expected;
  };
  const Broken cases[] = {
      {"unbalanced_disc_jenkins", "exponent = 2", "exponent = -2", "forcing_growth.exponent: must be >= 0"},
      {"unbalanced_disc_jenkins", "reference_frequency = 1.0", "", "forcing_growth.reference_frequency: missing"},
      {"shaker_base_motion", "dofs = [\"x1\", \"x2\"]      # the dofs the table", "dofs = [\"x1\", \"x3\"]      # the dofs the table",
       "base_motion.dofs[1]: unknown dof 'x3'"},
  };
  for (const Broken& b : cases) {
    std::ifstream in(hbtrack::test::source_path(std::string("examples/") + b.example + ".toml"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find(b.from), std::string(b.from).size(), b.to);
    const fs::path bad = fs::temp_directory_path() / ("hbtrack_cli_bad_" + std::to_string(getpid()) + "_" + b.example + ".toml");
    std::ofstream(bad) << text;
    const CliRun r = run_cli("frc " + bad.string() + " -o " + (fs::temp_directory_path() / "hbtrack_cli_bad_excitation_out").string());
    EXPECT_EQ(r.exit_code, 2) << b.expected;
    EXPECT_EQ(r.err.rfind("hbtrack: " + bad.string() + ":", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(b.expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST(Cli, FailedContinuationKeepsItsPointsAndExitsNonZero) {
  const fs::path out = fs::temp_directory_path() / "hbtrack_cli_fail";
  fs::remove_all(out);
  // A point budget far below what the range needs is not a failure (max_points), but a
  // tolerance below machine precision makes every corrector fail after the first point.
  const CliRun r = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " --set continuation.tolerance=1e-30 -o " +
                           out.string() + " -q");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("continuation stopped"), std::string::npos) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["stop_reason"], "no_convergence_at_start");
  EXPECT_EQ(hbtrack::test::count_lines(out / "branch.csv"), 1) << "a header and no point";

  // A failure part-way: two Newton iterations per step (plain Newton: chord steps converge
  // more slowly) cannot reach 1e-13 once the response grows nonlinear (near omega = 1), and
  // step_min = step leaves no room to halve. It fails after about 100 points (104 at 1e-13, 113
  // at 1e-14; at 1e-12 the steps sized by the branch's turn are short enough to get through),
  // so at least 10 is safe.
  fs::remove_all(out);
  const CliRun mid = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") +
                             " --set continuation.reuse_factorization=false --set continuation.max_iterations=2"
                             " --set continuation.step_min=0.02 --set continuation.tolerance=1e-13 -o " +
                             out.string() + " -q");
  EXPECT_EQ(mid.exit_code, 1);
  EXPECT_NE(mid.err.find("continuation stopped: step_size_underflow"), std::string::npos) << mid.err;
  const nlohmann::json m = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(m["stop_reason"], "step_size_underflow");
  EXPECT_GE(m["points"].get<int>(), 10);
  // The points accepted before the failure are on disk, one row each.
  EXPECT_EQ(hbtrack::test::count_lines(out / "branch.csv"), 1 + m["points"].get<int>());
  EXPECT_EQ(hbtrack::test::count_lines(out / "states.csv"), 1 + m["points"].get<int>());
}

// `frc --from DIR`: an NFRC stopped at omega = 1 extended to the case's omega_end from its last
// point finds the limit points of the run over the whole range. Both are located on the zero of
// their test function with the Newton tolerance 1e-9 of the residual, so they agree to well below
// 1e-8 although the two runs step differently (measured: 1.3e-11).
TEST(Cli, FrcFromAPointOfAnotherResultExtendsItsRange) {
  const fs::path out = fs::temp_directory_path() / ("hbtrack_cli_frc_from_" + std::to_string(getpid()));
  fs::remove_all(out);
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  ASSERT_EQ(run_cli("frc " + duffing + " -o " + (out / "full").string() + " -q").exit_code, 0);
  ASSERT_EQ(run_cli("frc " + duffing + " --set continuation.omega_end=1.0 -o " + (out / "first").string() + " -q").exit_code, 0);
  const CliRun extended = run_cli("frc " + duffing + " --from " + (out / "first").string() + " -o " + (out / "rest").string() + " -q");
  ASSERT_EQ(extended.exit_code, 0) << extended.err;
  const auto summary = [&](const char* name) { return nlohmann::json::parse(std::ifstream(out / name / "summary.json")); };
  const nlohmann::json full = summary("full"), first = summary("first"), rest = summary("rest");
  EXPECT_EQ(first["special_points"].size(), 0u);
  EXPECT_EQ(rest["stop_reason"], "reached_end");
  EXPECT_EQ(rest["started_from"]["point"].get<int>(), first["points"].get<int>() - 1);
  EXPECT_DOUBLE_EQ(rest["started_from"]["omega"].get<double>(), 1.0);
  ASSERT_EQ(rest["special_points"].size(), full["special_points"].size());
  for (size_t i = 0; i < full["special_points"].size(); ++i) {
    EXPECT_EQ(rest["special_points"][i]["type"], full["special_points"][i]["type"]);
    EXPECT_NEAR(rest["special_points"][i]["omega"].get<double>(), full["special_points"][i]["omega"].get<double>(), 1e-8);
  }
  // Its first row is the point it started from.
  const auto rows = hbtrack::test::csv_records(out / "rest" / "branch.csv");
  ASSERT_FALSE(rows.empty());
  EXPECT_DOUBLE_EQ(rows.front().at("omega"), 1.0);

  // A chosen row, and the errors that name the flag and the rule.
  ASSERT_EQ(run_cli("frc " + duffing + " --from " + (out / "full").string() + " --point 3 --set continuation.omega_end=0.6 -o " +
                    (out / "back").string() + " -q")
                .exit_code,
            0);
  EXPECT_EQ(summary("back")["stop_reason"], "reached_end");
  const CliRun beyond = run_cli("frc " + duffing + " --from " + (out / "first").string() + " --point 999 -o " + (out / "x").string());
  EXPECT_EQ(beyond.exit_code, 2);
  EXPECT_NE(beyond.err.find("--point: 999 is beyond the last point"), std::string::npos) << beyond.err;
  const CliRun at_end = run_cli("frc " + duffing + " --from " + (out / "full").string() + " -o " + (out / "x").string());
  EXPECT_EQ(at_end.exit_code, 2);
  EXPECT_NE(at_end.err.find("--set continuation.omega_end=VALUE"), std::string::npos) << at_end.err;
  EXPECT_EQ(run_cli("frc " + duffing + " --point 3 -o " + (out / "x").string()).exit_code, 2);
  fs::remove_all(out);
}

}  // namespace hbtrack_tests::file_cli
