// `hbtrack track` and `hbtrack isolas` end to end on the Duffing example: result contract,
// starting from a frc limit point, one-line errors for bad flags.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::csv_header;
using hbtrack::test::run_cli;

namespace {

const std::string kDuffing = hbtrack::test::source_path("examples/duffing.toml");

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(std::ifstream(p)); }

// A frc result of the Duffing example, shared by the tests of this file (per process).
fs::path duffing_frc() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("hbtrack_track_frc_" + std::to_string(getpid()));
    fs::remove_all(d);
    const CliRun r = run_cli("frc " + kDuffing + " -o " + d.string() + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return d;
  }();
  return dir;
}

TEST(TrackCli, FollowsTheFirstLimitPointInAmplitudeToItsCusp) {
  const fs::path out = fs::temp_directory_path() / ("hbtrack_track_" + std::to_string(getpid()));
  fs::remove_all(out);
  const CliRun r = run_cli("track " + kDuffing + " --from " + duffing_frc().string() + " --lp 1 --param amplitude --range 0.25:2 -o " +
                           out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = read_json(out / "summary.json");
  EXPECT_EQ(s["verb"], "track");
  EXPECT_EQ(s["stop_reason"], "completed");
  EXPECT_EQ(s["options"]["tracking"]["method"], "bordered");
  EXPECT_EQ(s["legs"].size(), 2u);
  ASSERT_EQ(s["special_points"].size(), 1u);
  EXPECT_EQ(s["special_points"][0]["type"], "min");
  EXPECT_TRUE(s["special_points"][0]["located"].get<bool>());
  EXPECT_NEAR(s["start"]["omega"].get<double>(), 1.2696, 1e-3);
  const std::vector<std::string> expected{"leg", "omega", "amplitude", "max_x", "min_x", "h1_x"};
  EXPECT_EQ(csv_header(out / "branch.csv"), expected);
  EXPECT_EQ(csv_header(out / "states.csv").size(), 3u + 15u);  // leg, omega, amplitude, 2H+1 harmonics

  // The isolas at amplitude 1.5: the curve crosses it twice, at the two LPs of the main branch
  // (the continuation from each reaches the frequency range: "open"), and there is no isola.
  const fs::path isolas = fs::temp_directory_path() / ("hbtrack_isolas_" + std::to_string(getpid()));
  fs::remove_all(isolas);
  const CliRun i = run_cli("isolas " + kDuffing + " --from " + out.string() + " --at 1.5 -o " + isolas.string() + " -q");
  ASSERT_EQ(i.exit_code, 0) << i.err;
  const nlohmann::json si = read_json(isolas / "summary.json");
  EXPECT_EQ(si["isolas"], 0);
  ASSERT_EQ(si["crossings"].size(), 2u);
  for (const auto& c : si["crossings"]) EXPECT_TRUE(c["status"] == "open" || c["status"] == "duplicate") << c.dump();
  EXPECT_EQ(si["crossings"][0]["status"], "open");
}

TEST(TrackCli, ReadsSubnormalHarmonicsBackAsNumbers) {
  // A harmonic at round-off level can be written as a subnormal (1e-322); reading it back must
  // not fail (std::stod rejects it as out of range).
  const fs::path copy = fs::temp_directory_path() / ("hbtrack_track_subnormal_" + std::to_string(getpid()));
  fs::remove_all(copy);
  fs::copy(duffing_frc(), copy);
  std::ifstream in(copy / "special_states.csv");
  std::string header, row, rest, line;
  std::getline(in, header);
  std::getline(in, row);
  while (std::getline(in, line)) rest += line + "\n";
  in.close();
  const size_t second = row.find(',', row.find(',') + 1);  // x0 is the zero harmonic (zero for Duffing)
  row = row.substr(0, row.find(',') + 1) + "1.0869444208507424e-322" + row.substr(second);
  std::ofstream(copy / "special_states.csv") << header << "\n" << row << "\n" << rest;
  const fs::path out = fs::temp_directory_path() / ("hbtrack_track_subnormal_out_" + std::to_string(getpid()));
  const CliRun r = run_cli("track " + kDuffing + " --from " + copy.string() + " --lp 1 --param amplitude --range 0.5:1.5 -o " + out.string() +
                           " -q");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(TrackCli, BadFlagsFailWithOneLineNamingTheFlag) {
  const std::string from = duffing_frc().string();
  const std::string out = " -o " + (fs::temp_directory_path() / "hbtrack_track_bad").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--lp 3 --param amplitude --range 0.5:2", "--lp: 3 is beyond the 2 limit points"},
      {"--lp 0 --param amplitude --range 0.5:2", "--lp: must be an integer >= 1"},
      {"--lp 1 --param stiffness --range 0.5:2", "--param: unknown parameter 'stiffness'"},
      {"--lp 1 --param amplitude --range 2:0.5", "--range: must be LO:HI with LO < HI"},
      {"--lp 1 --param amplitude --range 0.5", "--range: expected LO:HI"},
      {"--lp 1 --param amplitude --range 1.5:2", "--range: must contain amplitude = 1"},
      {"--lp 1 --param amplitude --range 0.5:2 --method newton", "--method: must be bordered or extended"},
  };
  for (const auto& [flags, message] : cases) {
    const CliRun r = run_cli("track " + kDuffing + " --from " + from + " " + flags + out);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(message), std::string::npos) << flags << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << " -> " << r.err;
  }
  const CliRun not_track = run_cli("isolas " + kDuffing + " --from " + from + " --at 1.5" + out);
  EXPECT_EQ(not_track.exit_code, 2);
  EXPECT_NE(not_track.err.find("options.tracking.parameter missing"), std::string::npos) << not_track.err;
}

}  // namespace
