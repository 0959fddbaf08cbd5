// `hbtrack track --ns K` / `--pd K` end to end: the NS curve of the nonlinear absorber
// (examples/nltva.toml) with its NS frequency per row and its extrema, and one-line errors for a
// point that is not there or a request that mixes kinds.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_ns_track_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;

namespace {

const std::string kAbsorberCase = hbtrack::test::source_path("examples/nltva.toml");

// A frc result of the absorber at A = 0.12 (two NS points, 1.1096 and 1.2247), shared per process.
fs::path absorber_frc() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("hbtrack_ns_track_frc_" + std::to_string(getpid()));
    fs::remove_all(d);
    const CliRun r = run_cli("frc " + kAbsorberCase + " -o " + d.string() + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return d;
  }();
  return dir;
}

}  // namespace

TEST(NsTrackCli, WritesTheNsCurveWithItsFrequencyAndExtrema) {
  const fs::path out = fs::temp_directory_path() / ("hbtrack_ns_track_" + std::to_string(getpid()));
  fs::remove_all(out);
  const CliRun r = run_cli("track " + kAbsorberCase + " --from " + absorber_frc().string() +
                           " --ns 2 --param amplitude --range 0.05:0.35 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = hbtrack::test::csv_records(out / "branch.csv");
  ASSERT_GT(rows.size(), 10u);
  // Row 0 is the NFRC's NS 2 (1.2247 rad/s at A = 0.12), its NS frequency in (0, w/2).
  EXPECT_NEAR(rows.front().at("omega"), 1.2247, 1e-4);
  EXPECT_NEAR(rows.front().at("amplitude"), 0.12, 1e-12);
  for (const auto& row : rows) {
    EXPECT_GE(row.at("ns_frequency"), 0.0);
    EXPECT_LE(row.at("ns_frequency"), 0.5 * row.at("omega"));
  }
  const nlohmann::json s = hbtrack::test::read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "completed");
  EXPECT_EQ(s["options"]["tracking"]["point"], "NS");
  EXPECT_EQ(s["options"]["tracking"]["ns"], 2);
  std::vector<std::string> types;
  for (const auto& p : s["special_points"]) {
    types.push_back(p["type"]);
    EXPECT_TRUE(p.contains("ns_frequency")) << p.dump();
  }
  // The band is born at the minimum in A and ends on the fold curve at both ends (NS frequency 0).
  EXPECT_EQ(std::count(types.begin(), types.end(), "min"), 1) << s["special_points"].dump();
  EXPECT_EQ(std::count(types.begin(), types.end(), "resonance_1_1"), 2) << s["special_points"].dump();
  for (const auto& leg : s["legs"]) EXPECT_EQ(leg["stop_reason"], "strong_resonance");
}

TEST(NsTrackCli, BadPointsFailWithOneLineNamingTheFlag) {
  const std::string from = absorber_frc().string();
  const std::string out = " -o " + (fs::temp_directory_path() / "hbtrack_ns_track_bad").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--ns 3 --param amplitude --range 0.05:0.35", "--ns: 3 is beyond the 2 NS points"},
      {"--ns 0 --param amplitude --range 0.05:0.35", "--ns: must be an integer >= 1"},
      {"--pd 1 --param amplitude --range 0.05:0.35", "--pd: " + from + "/summary.json has no PD points"},
      {"--ns 1 --lp 1 --param amplitude --range 0.05:0.35", "--lp and --ns: give one point to track"},
      {"--ns 1 --param amplitude --range 0.05:0.35 --method extended", "--method: --ns tracks on the bordered Hill pencil only"},
      {"--param amplitude --range 0.05:0.35", "--lp, --ns or --pd is required"},
  };
  for (const auto& [flags, message] : cases) {
    const CliRun r = run_cli("track " + kAbsorberCase + " --from " + from + " " + flags + out);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(message), std::string::npos) << flags << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << " -> " << r.err;
  }
}

TEST(NsTrackCli, IsolasRefusesAnNsCurveInOneLine) {
  // isolas follows the branch through a limit point at each crossing: an NS curve has none.
  const fs::path ns = fs::temp_directory_path() / ("hbtrack_ns_track_for_isolas_" + std::to_string(getpid()));
  fs::remove_all(ns);
  ASSERT_EQ(run_cli("track " + kAbsorberCase + " --from " + absorber_frc().string() + " --ns 1 --param amplitude --range 0.05:0.35 -q -o " +
                    ns.string())
                .exit_code,
            0);
  const CliRun r = run_cli("isolas " + kAbsorberCase + " --from " + ns.string() + " --at 0.13 -o " + (ns.string() + "_isolas"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("is a curve of NS points; isolas takes limit-point curves"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace hbtrack_tests::file_ns_track_cli
