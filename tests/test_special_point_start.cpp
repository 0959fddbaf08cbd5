// Which special point of an earlier result a run starts from (runs/special_point_start.hpp): the
// one choice that the CLI (track --lp/--ns/--pd, torus --ns, switch --point) and Python
// (lp=, ns=, pd=, point=) both make, and the errors both report.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <functional>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/special_point_start.hpp"

namespace hbtrack_tests::file_special_point_start {

using namespace hbtrack;
using nlohmann::json;

// summary.json's special_points of a downward sweep: met from the highest omega.
json downward_sweep() {
  return json::parse(R"([{"type": "LP", "index": 40, "omega": 1.3}, {"type": "BP", "index": 42, "omega": 1.25},
                         {"type": "PD", "index": 50, "omega": 1.2}, {"type": "LP", "index": 60, "omega": 1.1},
                         {"type": "min", "index": 61, "omega": 1.0}])");
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const CaseError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SpecialPointStart, PointsOfATypeAreNumberedInIncreasingOmega) {
  const json points = downward_sweep();
  EXPECT_EQ(runs::special_point_rows(points, SpecialPointType::limit_point), (std::vector<size_t>{3, 0}));
  EXPECT_TRUE(runs::special_point_is(points[1], SpecialPointType::branch_point));
  EXPECT_FALSE(runs::special_point_is(points[4], SpecialPointType::limit_point));  // a name of another table
  EXPECT_EQ(runs::special_point_index(points, SpecialPointType::limit_point, 1, {"--lp", "f"}), 3u);
  EXPECT_EQ(runs::special_point_index(points, SpecialPointType::limit_point, 2, {"--lp", "f"}), 0u);
  EXPECT_EQ(runs::special_point_index(points, SpecialPointType::period_doubling, 1, {"pd", "f"}), 2u);
}

TEST(SpecialPointStart, AMissingPointIsACaseErrorNamingTheKeywordAndTheResult) {
  const json points = downward_sweep();
  EXPECT_EQ(error_of([&] {
              runs::special_point_index(points, SpecialPointType::limit_point, 3, {"--lp", "DIR/summary.json"});
            }),
            "--lp: 3 is beyond the 2 limit points of DIR/summary.json");
  EXPECT_EQ(error_of([&] {
              runs::special_point_index(points, SpecialPointType::neimark_sacker, 1, {"ns", "the frc result"});
            }),
            "ns: the frc result has no NS points (an NFRC computed with stability finds them)");
  EXPECT_EQ(error_of([&] {
              runs::special_point_index(points, SpecialPointType::limit_point, 0, {"lp", "the frc result"});
            }),
            "lp: must be an integer >= 1, got 0");
}

TEST(SpecialPointStart, SwitchTakesABranchPointOrAPeriodDoublingAndItsNeighbours) {
  const json points = downward_sweep();
  const runs::SwitchPoint bp = runs::switch_point(points, 2, 100, {"--point", "f"});
  EXPECT_EQ(bp.type, SpecialPointType::branch_point);
  EXPECT_EQ(bp.special_row, 1u);
  EXPECT_EQ(bp.before_row, 41u);
  EXPECT_EQ(bp.after_row, 43u);
  const runs::SwitchPoint pd = runs::switch_point(points, 3, 51, {"--point", "f"});
  EXPECT_EQ(pd.type, SpecialPointType::period_doubling);
  EXPECT_EQ(pd.after_row, 50u);  // the last row: no neighbour beyond it
  EXPECT_EQ(error_of([&] {
              runs::switch_point(points, 1, 100, {"point", "the frc result"});
            }),
            "point: special point 1 of the frc result is a LP; switch follows the new branch of a BP or the period-doubled branch "
            "of a PD");
  EXPECT_EQ(error_of([&] {
              runs::switch_point(points, 6, 100, {"point", "the frc result"});
            }),
            "point: 6 is beyond the 5 special points of the frc result");
  EXPECT_EQ(error_of([&] {
              runs::switch_point(points, 2, 42, {"point", "the frc result"});
            }),
            "point: special point 2 of the frc result: index 42 is outside the branch's states");
}

}  // namespace hbtrack_tests::file_special_point_start
