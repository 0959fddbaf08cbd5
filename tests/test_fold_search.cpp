// `simulate --near-lp K` (hbtrack/runs/fold_search.hpp): which rows of an NFRC it starts from,
// how it decides that a time integration left the orbit, and the search end to end on Duffing's
// resonant fold, where the harmonic balance at H = 7 is exact to far below the 0.2 % of the
// first start, so the full model must hold the orbit there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/fold_search.hpp"
#include "test_support.hpp"

namespace hbtrack_tests::file_fold_search {

namespace fs = std::filesystem;
using hbtrack::runs::fold_search_rows;
using hbtrack::runs::FoldSearchCandidate;
using hbtrack::runs::FoldSearchRow;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;

namespace {
const std::string kDuffing = hbtrack::test::source_path("examples/duffing.toml");

// A fold at omega 1.0 reached at row 5: rows 0-4 climb the stable resonant branch towards it
// (omega 0.95 ... 0.999), rows 6-9 come back along the unstable branch.
std::vector<FoldSearchRow> fold_at_row_five(bool stable_before = true) {
  std::vector<FoldSearchRow> rows;
  for (double omega : {0.95, 0.97, 0.99, 0.995, 0.999}) rows.push_back({omega, stable_before, 2.0});
  rows.push_back({1.0, true, 1.8});
  for (double omega : {0.999, 0.995, 0.99, 0.97}) rows.push_back({omega, !stable_before, 1.5});
  return rows;
}
}  // namespace

TEST(FoldSearchRows, TakesTheStableSideClosestFirstEachRowOnce) {
  const auto picked = fold_search_rows(fold_at_row_five(), 5, 1.0, {0.002, 0.005, 0.01, 0.02, 0.03, 0.1}, "b.csv");
  // 0.2 % and 0.5 % are both first reached by row 3 (0.5 %): one start there; 1 % by row 2, 2 %
  // and 3 % by row 1; 10 % by no row of the stretch.
  ASSERT_EQ(picked.size(), 3u);
  EXPECT_EQ(picked[0].row, 3);
  EXPECT_NEAR(picked[0].distance, 0.005, 1e-12);
  EXPECT_EQ(picked[1].row, 2);
  EXPECT_EQ(picked[2].row, 1);
  EXPECT_DOUBLE_EQ(picked[2].omega, 0.97);
}

TEST(FoldSearchRows, FollowsTheBranchToWhicheverSideIsStable) {
  const auto picked = fold_search_rows(fold_at_row_five(false), 5, 1.0, {0.002, 0.01}, "b.csv");
  ASSERT_EQ(picked.size(), 2u);
  EXPECT_EQ(picked[0].row, 7);  // 0.5 % after the fold
  EXPECT_EQ(picked[1].row, 8);
}

TEST(FoldSearchRows, StopsWhereTheStableStretchEnds) {
  auto rows = fold_at_row_five();
  rows[2].stable = false;  // an NS band between rows 1 and 3
  const auto picked = fold_search_rows(rows, 5, 1.0, {0.002, 0.01, 0.03}, "b.csv");
  ASSERT_EQ(picked.size(), 1u);
  EXPECT_EQ(picked[0].row, 3);
}

TEST(FoldSearchRows, NoStableSideIsACaseErrorNamingTheFile) {
  auto rows = fold_at_row_five();
  for (auto& r : rows) r.stable = false;
  try {
    fold_search_rows(rows, 5, 1.0, {0.002}, "out/nfrc/branch.csv");
    FAIL() << "no error";
  } catch (const hbtrack::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("out/nfrc/branch.csv: neither side of the limit point (row 5) is stable"), std::string::npos)
        << e.what();
  }
}

TEST(OrbitDeparture, IsTheLargestRelativeChangeOfAFirstHarmonic) {
  const nlohmann::json s = {{"start", {{"h1_a", 2.0}, {"h1_b", 1.0}, {"max_a", 5.0}}}, {"h1_a", 2.1}, {"h1_b", 0.7}, {"max_a", 0.0}};
  EXPECT_NEAR(hbtrack::runs::orbit_departure(s), 0.3, 1e-12);                     // h1_b; max_ is not a first harmonic
  EXPECT_EQ(hbtrack::runs::orbit_departure(nlohmann::json{{"h1_a", 1.0}}), 0.0);  // from rest: nothing to leave
}

TEST(SimulateNearLp, HoldsDuffingsResonantFoldFromTheFirstStart) {
  const fs::path nfrc = fs::temp_directory_path() / "hbtrack_fold_search_nfrc";
  const fs::path out = fs::temp_directory_path() / "hbtrack_fold_search";
  fs::remove_all(nfrc);
  fs::remove_all(out);
  ASSERT_EQ(run_cli("frc " + kDuffing + " -o " + nfrc.string() + " -q").exit_code, 0);
  const nlohmann::json frc = nlohmann::json::parse(std::ifstream(nfrc / "summary.json"));
  // Duffing's two folds in omega order: the resonant one (the peak's) is the upper, LP2.
  const CliRun r = run_cli("simulate " + kDuffing + " --from " + nfrc.string() + " --near-lp 2 --max-periods 400 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("the orbit held from row"), std::string::npos) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["stop_reason"], "completed");
  const nlohmann::json& search = s["fold_search"];
  EXPECT_EQ(search["lp"], 2);
  ASSERT_EQ(search["runs"].size(), 1u);
  const nlohmann::json& held = search["held"];
  EXPECT_TRUE(held["held"].get<bool>());
  EXPECT_GE(held["distance"].get<double>(), 0.002);
  EXPECT_LT(held["omega"].get<double>(), search["lp_omega"].get<double>());  // the resonant branch is below the fold
  // The integration it holds by: periodic, its first harmonic the HBM's to the time step's error
  // (256 steps a period: 1e-4; here within 1e-3) although the fold is 0.2 % away.
  const nlohmann::json run = nlohmann::json::parse(std::ifstream(out / held["folder"].get<std::string>() / "summary.json"));
  EXPECT_TRUE(run["converged"].get<bool>());
  EXPECT_LT(held["departure"].get<double>(), 1e-3);
  EXPECT_EQ(run["options"]["simulation"]["point"], held["point"]);
  EXPECT_TRUE(fs::exists(out / held["folder"].get<std::string>() / "signals.csv"));
}

TEST(SimulateNearLp, BadRequestsFailWithOneLine) {
  const fs::path nfrc = fs::temp_directory_path() / "hbtrack_fold_search_nostab";
  fs::remove_all(nfrc);
  ASSERT_EQ(run_cli("frc " + kDuffing + " --set stability.method=none -o " + nfrc.string() + " -q").exit_code, 0);
  const std::string out = " -o " + (fs::temp_directory_path() / "hbtrack_fold_search_bad").string();
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--near-lp 1", "--near-lp: needs --from, and neither --point nor --omega"},
      {"--from " + nfrc.string() + " --near-lp 1 --point 2", "--near-lp: needs --from, and neither --point nor --omega"},
      {"--from " + nfrc.string() + " --near-lp 0", "--near-lp: must be an integer >= 1"},
      {"--from " + nfrc.string() + " --near-lp 9", "--near-lp: 9 is beyond the 2 limit points"},
      {"--from " + nfrc.string() + " --near-lp 1", "no column stable: --near-lp needs an NFRC computed with stability on"},
      {"--from " + nfrc.string() + " --near-lp 1 --distances 1,0.5", "--distances: must increase"},
      {"--from " + nfrc.string() + " --near-lp 1 --distances 0,1", "--distances: must be a number > 0"},
  };
  for (const auto& [flags, message] : cases) {
    const CliRun r = run_cli("simulate " + kDuffing + " " + flags + out);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(message), std::string::npos) << flags << " -> " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << " -> " << r.err;
  }
}

}  // namespace hbtrack_tests::file_fold_search
