#pragma once
// Special points found by a run against reference ones (type and omega, in the order found),
// within issue 34's bounds: 1e-7 relative for folds and branch points, 1e-5 for PD/NS points
// (Floquet multipliers, whose own accuracy allows that). Both runs locate the zero of the same
// test function on the same branch to the corrector's tolerance.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack_tests {

// `type` as summary.json names it: the references read as a result file does.
struct SpecialPointReference {
  std::string type;
  double omega;
};

inline void expect_special_points_near(const std::vector<hbtrack::SpecialPoint>& found, const std::vector<SpecialPointReference>& reference,
                                       const std::string& label) {
  ASSERT_EQ(found.size(), reference.size()) << label;
  for (size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(found[i].type, hbtrack::parse_special_point_type(reference[i].type)) << label << " #" << i;
    EXPECT_TRUE(found[i].located) << label << " #" << i;
    const bool engine_test =
        found[i].type == hbtrack::SpecialPointType::limit_point || found[i].type == hbtrack::SpecialPointType::branch_point;
    const double bound = engine_test ? 1e-7 : 1e-5;
    EXPECT_NEAR(found[i].lambda, reference[i].omega, bound * reference[i].omega) << label << " " << found[i].type;
  }
}

}  // namespace hbtrack_tests
