// Time integration of the Duffing example against its harmonic balance solutions: agreement on
// the unique solution at omega = 1, and departure from an unstable solution of the middle branch
// onto one of the two stable ones.
#include <gtest/gtest.h>

#include <memory>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_timeint_duffing {

using namespace hbtrack;

CaseDefinition duffing() { return load_case(test::source_path("examples/duffing.toml")); }

std::unique_ptr<TimeIntegrator> make_integrator(const std::string& method, EquationOfMotion& eom) {
  if (method == "newmark") return std::make_unique<NewmarkIntegrator>(eom, NewmarkOptions{});
  return std::make_unique<DormandPrinceIntegrator>(eom, DormandPrinceOptions{});
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

class DuffingTimeIntegration : public ::testing::TestWithParam<std::string> {};

TEST_P(DuffingTimeIntegration, SteadyStateFromRestMatchesTheHbmExtremes) {
  const CaseDefinition c = duffing();
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const double omega = 1.0;
  // What `hbtrack solve` computes (H = 7).
  const FixedFrequencySolution hbm_solution = solve_at_frequency(hbm, omega, c.outputs, 1e-12, 60);
  ASSERT_TRUE(hbm_solution.converged);
  const OutputValues& expected = hbm_solution.recorded.outputs[0];

  EquationOfMotion eom(c.model, c.elements, c.parameters, omega);
  auto integrator = make_integrator(GetParam(), eom);
  const SteadyStateResult r = integrate_to_steady_state(*integrator, rest_state(1), c.outputs, SteadyStateOptions{});
  ASSERT_TRUE(r.converged) << r.stop_reason;
  const PeriodSummary& s = r.outputs[0];
  EXPECT_LT(relative(s.max, expected.max), 5e-3);
  EXPECT_LT(relative(s.min, expected.min), 5e-3);
  EXPECT_LT(relative(s.first_harmonic(), expected.h1), 5e-3);
  std::printf("[ measured ] %s: %d periods, %ld steps, max %.3e min %.3e h1 %.3e relative to HBM\n", GetParam().c_str(), r.periods,
              r.statistics.steps, relative(s.max, expected.max), relative(s.min, expected.min), relative(s.first_harmonic(), expected.h1));
}

TEST_P(DuffingTimeIntegration, LeavesAnUnstableMiddleBranchSolutionForAStableOne) {
  CaseDefinition c = duffing();
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult nfrc = compute_nfrc(hbm, c.nfrc, c.outputs);
  // The branch climbs the resonance to the first limit point, comes back along the unstable
  // middle branch to the second one, then goes on along the lower branch.
  std::vector<int> folds;
  for (const SpecialPoint& sp : nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point) folds.push_back(sp.index);
  ASSERT_EQ(folds.size(), 2u);
  const int first_fold = folds[0], second_fold = folds[1];
  ASSERT_GT(second_fold - first_fold, 2);
  const auto& points = nfrc.continuation.points;
  const int middle = (first_fold + second_fold) / 2;
  const double omega = points[static_cast<size_t>(middle)].lambda;
  const double start_h1 = nfrc.recorded[static_cast<size_t>(middle)].outputs[0].h1;

  // The two stable solutions at this omega: Newton from the states of the upper segment (before
  // the first fold) and of the lower one (after the second) interpolated at omega.
  std::vector<double> stable_h1;
  for (const auto& [first, last] : {std::pair{0, first_fold}, std::pair{second_fold, static_cast<int>(points.size()) - 1}}) {
    for (int i = first; i < last; ++i) {
      const BranchPoint &a = points[static_cast<size_t>(i)], &b = points[static_cast<size_t>(i + 1)];
      if ((a.lambda - omega) * (b.lambda - omega) > 0) continue;
      const double w = (omega - a.lambda) / (b.lambda - a.lambda);
      const Eigen::VectorXd guess = (1 - w) * a.u + w * b.u;
      const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-12, 60, &guess);
      ASSERT_TRUE(s.converged);
      stable_h1.push_back(s.recorded.outputs[0].h1);
      break;
    }
  }
  ASSERT_EQ(stable_h1.size(), 2u);
  ASSERT_GT(std::abs(stable_h1[0] - stable_h1[1]), 0.5 * stable_h1[1]) << "two distinct stable solutions expected";

  EquationOfMotion eom(c.model, c.elements, c.parameters, omega);
  auto integrator = make_integrator(GetParam(), eom);
  const MotionState start =
      state_from_harmonics(hbm.expand(points[static_cast<size_t>(middle)].u, omega), 1, c.harmonic_balance.harmonics, omega);
  const SteadyStateResult r = integrate_to_steady_state(*integrator, start, c.outputs, SteadyStateOptions{});
  ASSERT_TRUE(r.converged) << r.stop_reason;
  const double final_h1 = r.outputs[0].first_harmonic();
  EXPECT_GT(std::abs(final_h1 - start_h1), 0.2 * start_h1) << "the motion stayed on the unstable solution";
  const double to_nearest = std::min(relative(final_h1, stable_h1[0]), relative(final_h1, stable_h1[1]));
  EXPECT_LT(to_nearest, 5e-3);
  std::printf("[ measured ] %s at omega %.4f: start h1 %.4f, stable h1 %.4f / %.4f, settled on %.4f (%.2e) after %d periods\n",
              GetParam().c_str(), omega, start_h1, stable_h1[0], stable_h1[1], final_h1, to_nearest, r.periods);
}

INSTANTIATE_TEST_SUITE_P(Methods, DuffingTimeIntegration, ::testing::Values("newmark", "dopri5"),
                         [](const ::testing::TestParamInfo<std::string>& method) { return method.param; });

}  // namespace hbtrack_tests::file_timeint_duffing
