// Continuation in a named parameter at fixed omega (`hbtrack continue`): the branch passes
// through the fixed-frequency solution, its folds in the forcing amplitude sit on the one-term
// analytic ones, stability flips exactly between them; the CLI's result contract and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "hbtrack/analysis/parameter_continuation.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_parameter_continuation {

using namespace hbtrack;
using Eigen::VectorXd;
namespace fs = std::filesystem;

namespace {

constexpr double kDamping = 0.05, kCubic = 0.1, kForce = 0.18;

CaseDefinition duffing(int harmonics) {
  return load_case(test::source_path("examples/duffing.toml"),
                   {"harmonic_balance.harmonics=" + std::to_string(harmonics), "continuation.tolerance=1e-11"});
}

// One-term balance at fixed w: F^2 = G(u) = u ((d + b u)^2 + g^2), u = a^2, d = 1 - w^2,
// b = 3/4 k3, g = c w. Folds in F where G'(u) = 3 b^2 u^2 + 4 b d u + d^2 + g^2 = 0; returns
// the forcing amplitudes (in units of kForce) of both, ascending.
std::vector<double> analytic_amplitude_folds(double w) {
  const double d = 1 - w * w, b = 0.75 * kCubic, g = kDamping * w;
  const double qa = 3 * b * b, qb = 4 * b * d, qc = d * d + g * g;
  const double disc = qb * qb - 4 * qa * qc;
  std::vector<double> folds;
  if (disc <= 0) return folds;
  for (const double u : {(-qb - std::sqrt(disc)) / (2 * qa), (-qb + std::sqrt(disc)) / (2 * qa)})
    folds.push_back(std::sqrt(u * ((d + b * u) * (d + b * u) + g * g)) / kForce);
  std::sort(folds.begin(), folds.end());
  return folds;
}

}  // namespace

TEST(ParameterContinuation, PassesThroughTheFixedFrequencySolutionAtTheNominalAmplitude) {
  const CaseDefinition c = duffing(7);
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const int amplitude = hbm.amplitude_parameter();
  const double omega = 1.0;  // below the fold region: one solution per amplitude
  // The engine lands exactly on the range's end, amplitude 1 = the case's nominal value.
  const ParameterBranchResult r = continue_in_parameter(hbm, amplitude, omega, 0.1, 1.0, c.nfrc, c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  const BranchPoint& last = r.continuation.points.back();
  EXPECT_EQ(last.lambda, 1.0);
  hbm.set_parameter(amplitude, 1.0);
  const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-11, 50);
  ASSERT_TRUE(s.converged);
  // Both converged to ||R|| <= 1e-11 * force scale (0.18); J's inverse is O(1/(c w)) = 20 at
  // most, so the two states agree to ~1e-11 * 0.18 * 20 = 4e-11; 1e-9 leaves room.
  EXPECT_LT((last.u - s.x).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(r.points.back().recorded.outputs[0].max, s.recorded.outputs[0].max, 1e-9);
  EXPECT_EQ(r.points.back().parameter, 1.0);
}

TEST(ParameterContinuation, LocatesBothFoldsOfTheAmplitudeSCurveOnTheOneTermOnes) {
  const double omega = 1.2;  // inside the resonance's fold region at amplitude 1: an S-curve
  const std::vector<double> expected = analytic_amplitude_folds(omega);
  ASSERT_EQ(expected.size(), 2u);
  ASSERT_LT(expected[1], 3.0);
  const CaseDefinition c = duffing(1);  // H = 1 is the one-term balance: folds agree to the tolerance
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const ParameterBranchResult r = continue_in_parameter(hbm, hbm.amplitude_parameter(), omega, 0.05, 3.0, c.nfrc, c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  std::vector<double> found;
  for (const SpecialPoint& sp : r.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point) {
      EXPECT_TRUE(sp.located);
      found.push_back(sp.lambda);
    }
  ASSERT_EQ(found.size(), 2u);
  std::sort(found.begin(), found.end());
  // Located by the secant on the tangent's lambda component to the Newton tolerance: 1e-7 on
  // an O(1) amplitude is the location's accuracy, not the model's.
  EXPECT_NEAR(found[0], expected[0], 1e-7);
  EXPECT_NEAR(found[1], expected[1], 1e-7);
  // The amplitude goes up, back down between the folds, up again: exactly the points where it
  // goes back down are unstable (a fold in F is a real multiplier crossing +1).
  for (size_t i = 1; i + 1 < r.points.size(); ++i) {
    const double dp = r.points[i + 1].parameter - r.points[i - 1].parameter;
    if (std::abs(dp) < 1e-3) continue;  // at a fold: the sign of dp is not resolved
    EXPECT_EQ(r.points[i].recorded.stable, dp > 0 ? 1 : 0) << "point " << i << " amplitude " << r.points[i].parameter;
  }
}

TEST(ContinueCli, WritesTheBranchWithTheParameterColumnAndItsFolds) {
  const fs::path out = fs::temp_directory_path() / ("hbtrack_continue_" + std::to_string(getpid()));
  fs::remove_all(out);
  const std::string duffing_case = test::source_path("examples/duffing.toml");
  const test::CliRun r =
      test::run_cli("continue " + duffing_case + " --param amplitude --omega 1.2 --range 0.05:3 -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["verb"], "continue");
  EXPECT_EQ(s["stop_reason"], "reached_end");
  EXPECT_EQ(s["options"]["continue"]["parameter"], "amplitude");
  int lps = 0;
  for (const auto& sp : s["special_points"]) {
    if (sp["type"] != "LP") continue;
    ++lps;
    EXPECT_EQ(sp["omega"].get<double>(), 1.2);
    EXPECT_EQ(sp["amplitude"].get<double>(), sp["parameters"]["amplitude"].get<double>());
  }
  EXPECT_EQ(lps, 2);
  // The historical columns first, then h0_x, h2_x .. h7_x and phase1_x .. phase7_x (H = 7), as
  // branch.csv of frc (docs/outputs.md).
  const std::vector<std::string> expected{"omega", "amplitude", "stable", "max_x", "min_x", "h1_x", "h0_x"};
  const std::vector<std::string> header = test::csv_header(out / "branch.csv");
  ASSERT_EQ(header.size(), 6u + 7u + 7u);
  EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 7), expected);
  EXPECT_EQ(header.back(), "phase7_x");
  EXPECT_EQ(test::csv_header(out / "states.csv").size(), 1u + 15u);  // omega, 2H+1 harmonics
  EXPECT_EQ(test::csv_header(out / "special_states.csv").size(), 1u + 15u);

  const test::CliRun bad = test::run_cli("continue " + duffing_case + " --param amplitud --omega 1.2 --range 0:2 -o " + out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--param"), std::string::npos) << bad.err;
  const test::CliRun bad_range = test::run_cli("continue " + duffing_case + " --param amplitude --omega 1.2 --range 2 -o " + out.string());
  EXPECT_EQ(bad_range.exit_code, 2);
  EXPECT_NE(bad_range.err.find("--range"), std::string::npos) << bad_range.err;
  fs::remove_all(out);
}

}  // namespace hbtrack_tests::file_parameter_continuation
