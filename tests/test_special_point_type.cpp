// The special points' types (util/special_point_type.hpp): every enumerator has one name that
// parses back to it, the names are the ones summary.json, the checkpoints and Python use, and an
// unknown name is refused with a message naming where it was read and every allowed name.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "choice_round_trip.hpp"
#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/util/special_point_type.hpp"

namespace hbtrack_tests::file_special_point_type {

using namespace hbtrack;

// The names are a file format: summary.json's special_points[].type holds them, and so do
// python/hbtrack/special_points.py's table and the readers of earlier results.
TEST(SpecialPointType, EveryEnumeratorRoundTripsThroughItsName) {
  EXPECT_EQ(round_trip_names<SpecialPointType>(), (std::vector<std::string>{"LP", "BP", "PD", "NS", "R1", "R2"}));
  EXPECT_EQ(round_trip_names<CurveExtremumType>(), (std::vector<std::string>{"min", "max", "resonance_1_1", "resonance_1_2"}));
  std::ostringstream printed;  // test messages and logs print the name
  printed << SpecialPointType::neimark_sacker << ' ' << CurveExtremumType::parameter_max;
  EXPECT_EQ(printed.str(), "NS max");
}

TEST(SpecialPointType, AnUnknownNameIsRefusedNamingWhereAndTheAllowedNames) {
  EXPECT_EQ(error_for<SpecialPointType>("lp"), "special point type: must be LP, BP, PD, NS, R1 or R2, got 'lp'");
  EXPECT_EQ(error_for<CurveExtremumType>("LP"),
            "tracking curve special point type: must be min, max, resonance_1_1 or resonance_1_2, got 'LP'");
  try {
    parse_special_point_type("", "run/summary.json: special_points[2].type");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "run/summary.json: special_points[2].type: must be LP, BP, PD, NS, R1 or R2, got ''");
  }
}

// What a tracking follows is a special point type too; a type no tracking follows is refused.
TEST(SpecialPointType, TrackedPointsAreTheirSpecialPointTypes) {
  for (const TrackedPoint tracked : {TrackedPoint::limit_point, TrackedPoint::neimark_sacker, TrackedPoint::period_doubling})
    EXPECT_EQ(parse_tracked_point(to_string(special_point_type(tracked)), "point"), tracked);
  EXPECT_EQ(special_point_type(TrackedPoint::neimark_sacker), SpecialPointType::neimark_sacker);
  try {
    parse_tracked_point("BP", "point");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "point: must be LP, NS or PD, got 'BP'");
  }
}

}  // namespace hbtrack_tests::file_special_point_type
