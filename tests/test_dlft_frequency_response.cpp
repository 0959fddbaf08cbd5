// The DLFT example as a frequency response (examples/frictional_contact_dlft.toml): its NFRC
// reaches the end of its range with default settings through the corners of the sampled
// stick-slip law (src/continuation/corner_step.hpp), and the penalty law's NFRC agrees with it as
// the penalty stiffness grows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

using namespace hbtrack;
using Eigen::VectorXd;

namespace {

const std::string kExample = "examples/frictional_contact_dlft.toml";

// The same model with the penalty law of normal and tangential stiffness k in place of DLFT.
HarmonicBalance penalty_model(const CaseDefinition& c, double k) {
  auto e = std::make_shared<FrictionalContact>();
  e->dofs = c.elements[0]->dofs;
  const double mu = c.elements[0]->property_values(c.parameters)[0];
  for (double v : {k, k, mu, 0.0}) e->properties.push_back(ParameterBinding::constant(v));
  return HarmonicBalance(c.model, ElementList{e}, c.parameters, c.harmonic_balance);
}

// The point of the branch at omega, where the branch crosses omega once: Newton at fixed omega
// from the chord between the two points around it (so the comparison is exact, not an
// interpolation).
VectorXd point_at(HarmonicBalance& hbm, const NfrcResult& r, double omega, const CaseDefinition& c) {
  const auto& p = r.continuation.points;
  int crossings = 0;
  VectorXd x;
  for (size_t i = 1; i < p.size(); ++i) {
    if ((p[i - 1].lambda - omega) * (p[i].lambda - omega) > 0) continue;
    ++crossings;
    const double f = (omega - p[i - 1].lambda) / (p[i].lambda - p[i - 1].lambda);
    x = p[i - 1].u + f * (p[i].u - p[i - 1].u);
  }
  EXPECT_EQ(crossings, 1) << "omega " << omega;
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-12, 50, &x);
  EXPECT_TRUE(s.converged) << "omega " << omega;
  return s.x;
}

}  // namespace

TEST(DlftFrequencyResponse, ExampleReachesTheEndOfItsRange) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "a minute under the sanitizers; DlftFrequencyResponse.CornersOfTheSampledLaw runs the same paths";
  const CaseDefinition c = load_case(test::source_path(kExample));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
  const ContinuationSummary& s = r.continuation.summary;
  std::printf("[ measured ] %d points, %d corners stepped onto or over, %d failed steps, %.2f s\n", s.points, s.corners_stepped_over,
              s.failed_steps, s.wall_s);
  ASSERT_EQ(s.stop_reason, "reached_end");
  EXPECT_NEAR(r.recorded.back().omega, c.nfrc.omega_end, 1e-12);
  EXPECT_GT(s.corners_stepped_over, 0) << "the range has corners the plain corrector cannot pass";
}
