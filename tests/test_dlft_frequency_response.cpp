// The DLFT example as a frequency response (examples/frictional_contact_dlft.toml, H = 5,
// N = 64, omega 0.3 -> 2): its residual is piecewise affine, with a piece per pattern of stick,
// slip and separated samples, and the branch turns at pattern changes by up to 170 degrees,
// where no point beyond the corner lies on the pseudo-arclength plane. Before the corner step
// (src/continuation/corner_step.hpp) the NFRC stopped with step_size_underflow at omega = 0.383;
// it now reaches the end of its range, on the branch that Newton from the linear solution finds
// at the frequencies where that converges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_dlft_frequency_response {

using namespace hbtrack;
using Eigen::VectorXd;

namespace {

const std::string kExample = "examples/frictional_contact_dlft.toml";

// The branch's point at omega, where the branch crosses omega exactly once: Newton at fixed omega
// from the chord between the two points around it, so that the comparison is between solutions,
// not an interpolation.
FixedFrequencySolution branch_point_at(HarmonicBalance& hbm, const NfrcResult& r, double omega, const CaseDefinition& c) {
  const auto& p = r.continuation.points;
  int crossings = 0;
  VectorXd chord;
  for (size_t i = 1; i < p.size(); ++i) {
    if ((p[i - 1].lambda - omega) * (p[i].lambda - omega) > 0) continue;
    ++crossings;
    const double f = (omega - p[i - 1].lambda) / (p[i].lambda - p[i - 1].lambda);
    chord = p[i - 1].u + f * (p[i].u - p[i - 1].u);
  }
  EXPECT_EQ(crossings, 1) << "omega " << omega;
  return solve_at_frequency(hbm, omega, c.outputs, 1e-12, 50, &chord);
}

}  // namespace

TEST(DlftFrequencyResponse, ExampleReachesTheEndOfItsRangeOnTheDirectSolutions) {
  const CaseDefinition c = load_case(test::source_path(kExample));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
  const ContinuationSummary& s = r.continuation.summary;
  std::printf("[ measured ] %d points, %d corners stepped onto or over, %d failed steps, %.2f s\n", s.points, s.corners_stepped_over,
              s.failed_steps, s.wall_s);
  ASSERT_EQ(s.stop_reason, StopReason::reached_end);
  EXPECT_NEAR(r.recorded.back().omega, c.nfrc.omega_end, 1e-12);
  EXPECT_GT(s.corners_stepped_over, 0) << "the range has corners the plain corrector cannot pass";
  // Newton from the linear solution (damped where plain Newton cycles between patterns) converges
  // across the range, and the branch passes through each of those independent solutions. Not at
  // omega = 1.0: there Newton lands on a second solution, 39 % larger, on an isolated branch (a
  // closed loop from omega 0.845 to 1.031 above this branch; docs/elements.md), which a sweep does
  // not reach. Both are Newton solutions to 1e-12 of the residual scale; 1e-8 of the largest
  // harmonic allows for the conditioning.
  for (double omega : {0.3, 0.5, 0.8, 0.85, 1.2, 1.5, 2.0}) {
    const FixedFrequencySolution direct = solve_at_frequency(hbm, omega, c.outputs, 1e-12, 3 * c.nfrc.continuation.max_iterations);
    ASSERT_TRUE(direct.converged) << "omega " << omega;
    const FixedFrequencySolution on_branch = branch_point_at(hbm, r, omega, c);
    ASSERT_TRUE(on_branch.converged) << "omega " << omega;
    const double gap = (on_branch.x - direct.x).cwiseAbs().maxCoeff() / direct.x.cwiseAbs().maxCoeff();
    std::printf("[ measured ] omega %.2f: branch against direct Newton %.2e\n", omega, gap);
    EXPECT_LT(gap, 1e-8) << "omega " << omega;
  }
}

}  // namespace hbtrack_tests::file_dlft_frequency_response
