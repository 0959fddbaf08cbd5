// `hbtrack track` and `hbtrack isolas` end to end on the Duffing example: result contract,
// starting from a frc limit point, one-line errors for bad flags.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_track_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::csv_header;
using hbtrack::test::run_cli;

namespace {

const std::string kDuffingCase = hbtrack::test::source_path("examples/duffing.toml");

using hbtrack::test::read_json;

// A frc result of the Duffing example, shared by the tests of this file (per process).
fs::path duffing_frc() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("hbtrack_track_frc_" + std::to_string(getpid()));
    fs::remove_all(d);
    const CliRun r = run_cli("frc " + kDuffingCase + " -o " + d.string() + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return d;
  }();
  return dir;
}

// LP2 is the upper fold (numbered in increasing omega), met first by the upward sweep.
TEST(TrackCli, FollowsTheUpperLimitPointInAmplitudeToItsCusp) {
  const fs::path out = fs::temp_directory_path() / ("hbtrack_track_" + std::to_string(getpid()));
  fs::remove_all(out);
  const CliRun r = run_cli("track " + kDuffingCase + " --from " + duffing_frc().string() + " --lp 2 --param amplitude --range 0.25:2 -o " +
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
  EXPECT_EQ(s["options"]["tracking"]["lp_order"], "omega");
  // The historical columns first, then h0_x, h2_x .. h7_x and phase1_x .. phase7_x (H = 7).
  const std::vector<std::string> expected{"leg", "omega", "amplitude", "max_x", "min_x", "h1_x", "h0_x"};
  const std::vector<std::string> header = csv_header(out / "branch.csv");
  ASSERT_EQ(header.size(), 6u + 7u + 7u);
  EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 7), expected);
  EXPECT_EQ(header.back(), "phase7_x");
  EXPECT_EQ(csv_header(out / "states.csv").size(), 3u + 15u);  // leg, omega, amplitude, 2H+1 harmonics

  // The isolas at amplitude 1.5: the curve crosses it twice, at the two LPs of the main branch
  // (the continuation from each reaches the frequency range: "open"), and there is no isola.
  const fs::path isolas = fs::temp_directory_path() / ("hbtrack_isolas_" + std::to_string(getpid()));
  fs::remove_all(isolas);
  const CliRun i = run_cli("isolas " + kDuffingCase + " --from " + out.string() + " --at 1.5 -o " + isolas.string() + " -q");
  ASSERT_EQ(i.exit_code, 0) << i.err;
  const nlohmann::json si = read_json(isolas / "summary.json");
  EXPECT_EQ(si["isolas"], 0);
  ASSERT_EQ(si["crossings"].size(), 2u);
  for (const auto& c : si["crossings"]) EXPECT_TRUE(c["status"] == "open" || c["status"] == "duplicate") << c.dump();
  EXPECT_EQ(si["crossings"][0]["status"], "open");

  // A limit point beyond the case's frequency range is reported, not followed.
  const CliRun narrow = run_cli("isolas " + kDuffingCase + " --from " + out.string() + " --at 1.5 --set continuation.omega_end=1.3 -o " +
                                isolas.string() + " -q");
  ASSERT_EQ(narrow.exit_code, 0) << narrow.err;
  int outside = 0;
  const nlohmann::json narrowed = read_json(isolas / "summary.json");  // kept alive: the loop refers into it
  for (const auto& c : narrowed["crossings"]) outside += c["status"] == "outside_range";
  EXPECT_EQ(outside, 1);
}

// The NLTVA example has a documented isola (examples/nltva.toml): its tracking curve shows where
// it is born and where it merges, `isolas` computes it at A = 0.15 where the NFRC from the linear
// solution does not reach it, and a simulation started on its stable part stays on it while one
// from rest settles on the main branch (the paper's Fig. 12).
TEST(TrackCli, FindsTheIsolaOfTheNonlinearAbsorberAndTimeIntegrationConfirmsIt) {
  const std::string nltva = hbtrack::test::source_path("examples/nltva.toml");
  const fs::path root = fs::temp_directory_path() / ("hbtrack_nltva_" + std::to_string(getpid()));
  fs::remove_all(root);
  const std::string frc = (root / "frc").string(), track = (root / "track").string(), isolas = (root / "isolas").string();
  ASSERT_EQ(run_cli("frc " + nltva + " -o " + frc + " -q").exit_code, 0);
  const CliRun t = run_cli("track " + nltva + " --from " + frc + " --lp 1 --param amplitude --range 0.01:0.4 -o " + track + " -q");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const nlohmann::json ts = read_json(fs::path(track) / "summary.json");
  bool born = false, merges = false;
  for (const auto& sp : ts["special_points"]) {
    const double w = sp["omega"], a = sp["amplitude"];
    born = born || (sp["type"] == "min" && std::abs(w - 1.80) < 0.01 && std::abs(a - 0.1247) < 1e-3);
    merges = merges || (sp["type"] == "max" && std::abs(w - 1.44) < 0.01 && std::abs(a - 0.1856) < 1e-3);
  }
  EXPECT_TRUE(born) << ts["special_points"].dump();
  EXPECT_TRUE(merges) << ts["special_points"].dump();

  const CliRun i = run_cli("isolas " + nltva + " --from " + track + " --at 0.15 -o " + isolas + " -q");
  ASSERT_EQ(i.exit_code, 0) << i.err;
  const nlohmann::json is = read_json(fs::path(isolas) / "summary.json");
  ASSERT_EQ(is["isolas"], 1) << is.dump();
  const fs::path isola = fs::path(isolas) / "isola_1";
  const nlohmann::json isola_summary = read_json(isola / "summary.json");
  EXPECT_EQ(isola_summary["stop_reason"], "closed");
  // Closed: the last row of states.csv repeats the first.
  std::ifstream states(isola / "states.csv");
  std::string header, first, line, last;
  std::getline(states, header);
  std::getline(states, first);
  while (std::getline(states, line)) last = line;
  EXPECT_EQ(first, last);
  // Detached: the main NFRC at the same amplitude stays below a third of the isola's smallest peak.
  const std::string main = (root / "main").string();
  ASSERT_EQ(run_cli("frc " + nltva + " --set amplitude=0.15 -o " + main + " -q").exit_code, 0);
  auto extreme_of_max_x1 = [](const fs::path& branch, double lo, double hi, bool smallest) {
    std::ifstream in(branch);
    std::string row;
    std::getline(in, row);
    const auto cols = csv_header(branch);
    const size_t col = static_cast<size_t>(std::find(cols.begin(), cols.end(), "max_x1") - cols.begin());
    double extreme = smallest ? 1e300 : 0.0;
    while (std::getline(in, row)) {
      std::vector<double> v;
      std::stringstream ss(row);
      for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
      if (v[0] < lo || v[0] > hi) continue;
      extreme = smallest ? std::min(extreme, v[col]) : std::max(extreme, v[col]);
    }
    return extreme;
  };
  const double isola_smallest = extreme_of_max_x1(isola / "branch.csv", 1.6, 2.3, true);
  EXPECT_LT(3.0 * extreme_of_max_x1(fs::path(main) / "branch.csv", 1.6, 2.3, false), isola_smallest);

  // Time integration on the isola's stable part (row 23 at the writing; any stable row with a
  // large amplitude will do) against a start from rest at the same frequency.
  std::ifstream branch(isola / "branch.csv");
  std::getline(branch, line);
  const auto cols = csv_header(isola / "branch.csv");
  const size_t stable_col = static_cast<size_t>(std::find(cols.begin(), cols.end(), "stable") - cols.begin());
  const size_t max_col = static_cast<size_t>(std::find(cols.begin(), cols.end(), "max_x1") - cols.begin());
  long row = -1, best = -1;
  double omega = 0, peak = 0;
  while (std::getline(branch, line)) {
    ++row;
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    if (v[stable_col] == 1.0 && v[max_col] > peak && v[0] > 1.8 && v[0] < 2.1) best = row, omega = v[0], peak = v[max_col];
  }
  ASSERT_GE(best, 0) << "no stable isola point between omega 1.8 and 2.1";
  const std::string on_isola = (root / "sim_isola").string(), from_rest = (root / "sim_rest").string();
  ASSERT_EQ(
      run_cli("simulate " + nltva + " --from " + isola.string() + " --point " + std::to_string(best) + " -o " + on_isola + " -q").exit_code,
      0);
  char omega_text[40];
  std::snprintf(omega_text, sizeof omega_text, "%.17g", omega);
  ASSERT_EQ(run_cli("simulate " + nltva + " --set amplitude=0.15 --omega " + omega_text + " -o " + from_rest + " -q").exit_code, 0);
  const double stays = read_json(fs::path(on_isola) / "summary.json")["max_x1"];
  const double rest = read_json(fs::path(from_rest) / "summary.json")["max_x1"];
  EXPECT_NEAR(stays, peak, 5e-3 * peak);  // the steady-state criterion of simulate, 0.5 %
  EXPECT_LT(3.0 * rest, peak);
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
  const CliRun r = run_cli("track " + kDuffingCase + " --from " + copy.string() + " --lp 1 --param amplitude --range 0.5:1.5 -o " +
                           out.string() + " -q");
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
    const CliRun r = run_cli("track " + kDuffingCase + " --from " + from + " " + flags + out);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(message), std::string::npos) << flags << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << " -> " << r.err;
  }
  const CliRun not_track = run_cli("isolas " + kDuffingCase + " --from " + from + " --at 1.5" + out);
  EXPECT_EQ(not_track.exit_code, 2);
  EXPECT_NE(not_track.err.find("options.tracking.parameter missing"), std::string::npos) << not_track.err;
}

TEST(TrackCli, TracksALimitPointOfTheC0LawThroughItsSampleMean) {
  // The two-dof example's unilateral spring is C0; averaged over each time sample (the AFT's
  // sample mean, scalar_elements.hpp) its harmonic balance residual is C1, so its limit points
  // can be tracked. Each point of the tracking curve is a fold of the NFRC at its amplitude:
  // an NFRC run at one of those amplitudes locates its fold at the same omega, to the
  // locators' accuracy (both are secants on test functions converged to 1e-9: 1e-6 relative).
  const std::string case_file = hbtrack::test::source_path("examples/two_dof_contact.toml");
  const fs::path base = fs::temp_directory_path() / ("hbtrack_track_c0_" + std::to_string(getpid()));
  fs::remove_all(base);
  // Stability plays no part in locating folds: off, the two NFRCs cost a tenth.
  const std::string no_stability = " --set 'stability.method=\"none\"'";
  ASSERT_EQ(run_cli("frc " + case_file + no_stability + " -o " + (base / "frc").string() + " -q").exit_code, 0);
  const CliRun r = run_cli("track " + case_file + " --from " + (base / "frc").string() + " --lp 1 --param amplitude --range 0.5:2 -q -o " +
                           (base / "track").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = hbtrack::test::csv_records(base / "track" / "branch.csv");
  ASSERT_GT(rows.size(), 10u);
  const auto& probe = rows[rows.size() * 3 / 4];  // on the leg towards larger amplitudes
  const double omega = probe.at("omega"), amplitude = probe.at("amplitude");
  char set[64];
  std::snprintf(set, sizeof set, "%.17g", amplitude);
  ASSERT_EQ(run_cli("frc " + case_file + no_stability + " -q --set amplitude=" + set + " -o " + (base / "check").string()).exit_code, 0);
  const nlohmann::json summary = read_json((base / "check" / "summary.json").string());
  double nearest = INFINITY;
  for (const auto& sp : summary["special_points"])
    if (sp["type"] == "LP") nearest = std::min(nearest, std::abs(sp["omega"].get<double>() - omega));
  EXPECT_LT(nearest, 1e-6 * omega) << "no NFRC fold at the tracked point (amplitude " << amplitude << ", omega " << omega << ")";
  fs::remove_all(base);
}

TEST(TrackCli, ATinyClosedCurveClosesOnceAndACappedLegIsNotCompleted) {
  // The two-dof example with a smooth law narrower than one time sample (sqrt, width 0.01, about
  // 2e-3 in displacement against 2e-2 between samples): its tracked fold is a loop in
  // (omega, amplitude) only about three continuation steps across. It used to go round it until
  // both legs hit max_points (584 extrema, stop_reason "completed"); it closes after one turn,
  // with one min and one max of the amplitude.
  const fs::path base = fs::temp_directory_path() / ("hbtrack_track_loop_" + std::to_string(getpid()));
  fs::remove_all(base);
  fs::create_directories(base);
  std::ifstream in(hbtrack::test::source_path("examples/two_dof_contact.toml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string toml = text.str();
  const std::string spring = "type = \"unilateral_spring\"";
  ASSERT_NE(toml.find(spring), std::string::npos);
  toml.replace(toml.find(spring), spring.size(), "type = \"regularized_contact\"\nlaw = \"sqrt\"\nwidth = 0.01");
  const std::string case_file = (base / "narrow_law.toml").string();
  std::ofstream(case_file) << toml;
  // On this law the upper fold is split into folds a few 1e-6 apart in omega (0.770066, 0.770080,
  // 0.770083 rad/s), real zeros of the LP test function; which one the NFRC brackets depends on its
  // steps. The one it finds with steps of at most 0.1 (the fixed cap before the steps were sized
  // by the branch) draws the loop this test is about; the one found at the default steps
  // (0.770083) draws a curve that winds round without passing within the closure test's quarter
  // step of its start (docs/performance.md, issue 34).
  const std::string nfrc = " --set 'stability.method=\"none\"' --set continuation.step_max=0.1";
  ASSERT_EQ(run_cli("frc " + case_file + nfrc + " -q -o " + (base / "frc").string()).exit_code, 0);
  const std::string track =
      "track " + case_file + " --from " + (base / "frc").string() + " --lp 2 --param amplitude --range 0.2:3 -q -o ";  // the upper fold
  const CliRun r = run_cli(track + (base / "track").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json loop = read_json((base / "track" / "summary.json").string());
  EXPECT_EQ(loop["stop_reason"], "closed");
  EXPECT_LT(loop["points"].get<int>(), 100);
  ASSERT_EQ(loop["special_points"].size(), 2u);
  EXPECT_NE(loop["special_points"][0]["type"], loop["special_points"][1]["type"]);

  // A leg cut by max_points: the curve is incomplete, and says so, also in the closing line (it
  // said "both ways to the range"). Without -q, for that line.
  const std::string unquiet = track.substr(0, track.find(" -q -o ")) + " -o ";
  const CliRun capped = run_cli(unquiet + (base / "capped").string() + " --set continuation.max_points=5");
  ASSERT_EQ(capped.exit_code, 0) << capped.err;
  EXPECT_NE(capped.err.find("leg 1 max_points, leg 2 max_points"), std::string::npos) << capped.err;
  EXPECT_EQ(capped.err.find("both ways to the range"), std::string::npos) << capped.err;
  const nlohmann::json cut = read_json((base / "capped" / "summary.json").string());
  EXPECT_EQ(cut["stop_reason"], "max_points");
  ASSERT_GE(cut["warnings"].size(), 1u);
  EXPECT_NE(cut["warnings"][0].get<std::string>().find("the curve is incomplete"), std::string::npos);
  fs::remove_all(base);
}

TEST(TrackCli, IsolasAtTheTrackedValueItselfFindsTheLimitPointTheCurveStartsFrom) {
  // Duffing's two limit points at A = 1 lie on one tracking curve, which starts at LP1. The
  // crossings of A = 1 are LP1 (the curve's first point, which the search used to skip: the
  // rotor 67 study's validations at the case's own mu and clearance found no crossing) and LP2.
  const fs::path base = fs::temp_directory_path() / ("hbtrack_isolas_at_start_" + std::to_string(getpid()));
  fs::remove_all(base);
  ASSERT_EQ(run_cli("frc " + kDuffingCase + " -q -o " + (base / "frc").string()).exit_code, 0);
  ASSERT_EQ(run_cli("track " + kDuffingCase + " --from " + (base / "frc").string() + " --lp 1 --param amplitude --range 0.1:2 -q -o " +
                    (base / "track").string())
                .exit_code,
            0);
  ASSERT_EQ(
      run_cli("isolas " + kDuffingCase + " --from " + (base / "track").string() + " --at 1 -q -o " + (base / "isolas").string()).exit_code,
      0);
  const nlohmann::json nfrc = read_json((base / "frc" / "summary.json").string());
  const nlohmann::json isolas = read_json((base / "isolas" / "summary.json").string());
  ASSERT_EQ(nfrc["special_points"].size(), 2u);
  ASSERT_EQ(isolas["crossings"].size(), 2u);
  for (const auto& lp : nfrc["special_points"]) {
    double nearest = INFINITY;
    for (const auto& c : isolas["crossings"]) nearest = std::min(nearest, std::abs(c["omega"].get<double>() - lp["omega"].get<double>()));
    EXPECT_LT(nearest, 1e-8) << "no crossing at the NFRC's limit point " << lp["omega"];  // both located to the Newton tolerance
  }
  fs::remove_all(base);
}

TEST(TrackCli, IsolasAtTheRangeEndACurveStartsFromFindsItsLimitPoint) {
  // Tracked over [1, 2] from Duffing's LP1 at A = 1, the curve's first leg (towards 1) ends where
  // it starts: two points, both at A = 1. The crossing of A = 1 is that first point all the same
  // (the search skipped segments of one value, and so lost it: the rotor 67 study's validation
  // at mu = 1e-4, the end of its range, found none on the curve started from its own LP).
  const fs::path base = fs::temp_directory_path() / ("hbtrack_isolas_at_range_end_" + std::to_string(getpid()));
  fs::remove_all(base);
  ASSERT_EQ(run_cli("frc " + kDuffingCase + " -q -o " + (base / "frc").string()).exit_code, 0);
  ASSERT_EQ(run_cli("track " + kDuffingCase + " --from " + (base / "frc").string() + " --lp 1 --param amplitude --range 1:2 -q -o " +
                    (base / "track").string())
                .exit_code,
            0);
  const nlohmann::json track = read_json((base / "track" / "summary.json").string());
  ASSERT_GE(track["legs"].size(), 1u);
  ASSERT_EQ(track["legs"][0]["points"], 2) << "the case this test is about: a first leg of two points at the range's end";
  ASSERT_EQ(
      run_cli("isolas " + kDuffingCase + " --from " + (base / "track").string() + " --at 1 -q -o " + (base / "isolas").string()).exit_code,
      0);
  // --lp 1 is the limit point of lowest omega (tracking's lp_order "omega").
  const nlohmann::json nfrc = read_json((base / "frc" / "summary.json").string());
  double lp1 = INFINITY;
  for (const auto& sp : nfrc["special_points"])
    if (sp["type"] == "LP") lp1 = std::min(lp1, sp["omega"].get<double>());
  const nlohmann::json isolas = read_json((base / "isolas" / "summary.json").string());
  double nearest = INFINITY;
  for (const auto& c : isolas["crossings"]) nearest = std::min(nearest, std::abs(c["omega"].get<double>() - lp1));
  EXPECT_LT(nearest, 1e-8) << "no crossing at LP1 " << lp1;  // both located to the Newton tolerance
  fs::remove_all(base);
}

}  // namespace

}  // namespace hbtrack_tests::file_track_cli
