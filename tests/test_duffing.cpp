// The Duffing example against the single-harmonic analytic solution, convergence in H, and the
// equation of motion checked in the time domain.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_duffing {

using namespace hbtrack;
using Eigen::VectorXd;

namespace {

constexpr double kDamping = 0.05, kCubic = 0.1, kForce = 0.18;

// One-term harmonic balance: ((1 - w^2 + 3/4 k3 a^2)^2 + (c w)^2) a^2 = F^2. Its largest a is
// where d/dw vanishes: 1 - w^2 + 3/4 k3 a^2 = c^2 / 2. Solved by fixed-point iteration.
void analytic_peak(double& omega, double& amplitude) {
  const double detuning = kDamping * kDamping / 2.0;
  amplitude = kForce / kDamping;
  for (int it = 0; it < 200; ++it) {
    omega = std::sqrt(1.0 + 0.75 * kCubic * amplitude * amplitude - detuning);
    amplitude = kForce / std::sqrt(detuning * detuning + kDamping * kDamping * omega * omega);
  }
}

struct Peak {
  double omega, max_x;
  int index;
};

// The largest max_x along the branch, refined by a parabola through the three points around it
// (the step error drops from O(ds^2) to O(ds^3)).
Peak branch_peak(const NfrcResult& r) {
  int best = 0;
  for (size_t i = 0; i < r.recorded.size(); ++i)
    if (r.recorded[i].outputs[0].max > r.recorded[static_cast<size_t>(best)].outputs[0].max) best = static_cast<int>(i);
  Peak p{r.recorded[static_cast<size_t>(best)].omega, r.recorded[static_cast<size_t>(best)].outputs[0].max, best};
  if (best > 0 && best + 1 < static_cast<int>(r.recorded.size())) {
    const double y0 = r.recorded[static_cast<size_t>(best - 1)].outputs[0].max, y1 = p.max_x,
                 y2 = r.recorded[static_cast<size_t>(best + 1)].outputs[0].max;
    const double s0 = -r.continuation.points[static_cast<size_t>(best)].step,
                 s2 = r.continuation.points[static_cast<size_t>(best + 1)].step;
    // Parabola through (s0, y0), (0, y1), (s2, y2) in arc length; its vertex value.
    const double a = ((y2 - y1) / s2 - (y0 - y1) / s0) / (s2 - s0);
    const double b = (y2 - y1) / s2 - a * s2;
    if (a < 0) p.max_x = y1 - b * b / (4 * a);
  }
  return p;
}

NfrcResult duffing_nfrc(int harmonics, double step = 0.01) {
  CaseDefinition c = load_case(
      test::source_path("examples/duffing.toml"),
      {"harmonic_balance.harmonics=" + std::to_string(harmonics), "harmonic_balance.samples=" + std::to_string(16 * (harmonics + 1)),
       "continuation.step=" + std::to_string(step), "continuation.step_max=" + std::to_string(step)});
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  return compute_nfrc(hbm, c.nfrc, c.outputs);
}

}  // namespace

TEST(Duffing, OneHarmonicPeakMatchesTheAnalyticSolution) {
  double omega_peak, a_peak;
  analytic_peak(omega_peak, a_peak);
  const NfrcResult r = duffing_nfrc(1);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  const Peak p = branch_peak(r);
  // With H = 1 the HBM is the one-term balance: only the peak sampling error remains (O(ds^3)).
  EXPECT_NEAR(p.max_x, a_peak, 1e-4 * a_peak);
  EXPECT_NEAR(p.omega, omega_peak, 5e-3);
}

TEST(Duffing, SevenHarmonicPeakDiffersOnlyByTheHigherHarmonics) {
  double omega_peak, a_peak;
  analytic_peak(omega_peak, a_peak);
  CaseDefinition c = load_case(test::source_path("examples/duffing.toml"), {"continuation.step=0.01", "continuation.step_max=0.01"});
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  const Peak p = branch_peak(r);
  // |max x - a1| is bounded by the sum of the harmonics above the first at the peak.
  const VectorXd& x = r.continuation.points[static_cast<size_t>(p.index)].u;
  double higher = 0;
  for (int j = 2; j <= 7; ++j) higher += std::hypot(x(2 * j - 1), x(2 * j));
  EXPECT_GT(higher, 1e-3) << "the test needs visible higher harmonics";
  EXPECT_LE(std::abs(p.max_x - a_peak), higher + 1e-3 * a_peak);
  EXPECT_NEAR(p.omega, omega_peak, 0.01);
  // Two limit points bracket the unstable middle branch.
  ASSERT_EQ(r.continuation.special_points.size(), 2u);
  EXPECT_EQ(r.continuation.special_points[0].type, SpecialPointType::limit_point);
  EXPECT_GT(r.continuation.special_points[0].lambda, r.continuation.special_points[1].lambda);
}

TEST(Duffing, PeakConvergesAsHarmonicsGrow) {
  std::vector<double> peaks;
  for (int h : {1, 3, 5, 7, 9}) peaks.push_back(branch_peak(duffing_nfrc(h)).max_x);
  const double reference = peaks.back();
  // Each added odd harmonic reduces the error by a large factor (spectral convergence).
  for (size_t i = 0; i + 2 < peaks.size(); ++i)
    EXPECT_LT(std::abs(peaks[i + 1] - reference), 0.3 * std::abs(peaks[i] - reference)) << "H index " << i;
  EXPECT_LT(std::abs(peaks[3] - reference), 1e-4 * reference);
}

TEST(Duffing, SolutionSatisfiesTheEquationOfMotionInTime) {
  std::vector<double> residuals;
  for (int h : {3, 5, 7, 9}) {
    CaseDefinition c = load_case(test::source_path("examples/duffing.toml"),
                                 {"harmonic_balance.harmonics=" + std::to_string(h), "harmonic_balance.samples=256"});
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    const double omega = 1.0;
    const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-12, 50);
    ASSERT_TRUE(s.converged);
    // x, x', x'' on a fine grid from the harmonics; residual of x'' + c x' + x + k3 x^3 - F cos.
    double worst = 0;
    const int grid = 2000;
    for (int i = 0; i < grid; ++i) {
      const double tau = 2.0 * std::numbers::pi * i / grid;
      double x = 0.5 * s.x(0), v = 0, a = 0;
      for (int j = 1; j <= h; ++j) {
        const double cj = s.x(2 * j - 1), sj = s.x(2 * j);
        x += cj * std::cos(j * tau) + sj * std::sin(j * tau);
        v += j * omega * (-cj * std::sin(j * tau) + sj * std::cos(j * tau));
        a += -j * j * omega * omega * (cj * std::cos(j * tau) + sj * std::sin(j * tau));
      }
      worst = std::max(worst, std::abs(a + kDamping * v + x + kCubic * x * x * x - kForce * std::cos(tau)));
    }
    residuals.push_back(worst / kForce);
  }
  // What remains is the cubic force's content above H, which falls quickly with H.
  EXPECT_LT(residuals[2], 1e-4) << "H = 7";
  for (size_t i = 0; i + 1 < residuals.size(); ++i) EXPECT_LT(residuals[i + 1], 0.2 * residuals[i]);
}

// Chord iterations (the default) against plain Newton on the same NFRC: the same special points,
// every point converged, and fewer factorizations. The limit points are located by a secant
// iteration on the tangent's omega component down to 1e-12 of the bracket, on branch points that
// each solve R = 0 to the tolerance 1e-9 (relative to the forcing); two such locations differ by
// the branch's sensitivity to that residual, the tolerance amplified by the conditioning near the
// fold: 1e-8 relative allows a factor 10 (they agree to 7e-12 on this machine).
TEST(Duffing, ChordIterationsFindTheSameLimitPointsWithFewerFactorizations) {
  NfrcResult runs[2];
  for (const bool reuse : {false, true}) {
    CaseDefinition c = load_case(test::source_path("examples/duffing.toml"),
                                 {std::string("continuation.reuse_factorization=") + (reuse ? "true" : "false")});
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    NfrcResult& r = runs[reuse ? 1 : 0];
    r = compute_nfrc(hbm, c.nfrc, c.outputs);
    ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end) << (reuse ? "chord" : "newton");
    // Every accepted point solves R = 0 to the tolerance, checked here independently.
    const double tolerance = c.nfrc.continuation.tolerance * force_scale(hbm, r.length_scale);
    VectorXd residual;
    for (const BranchPoint& p : r.continuation.points) {
      hbm.evaluate(p.u, p.lambda, residual);
      EXPECT_LE(residual.cwiseAbs().maxCoeff(), tolerance) << "omega " << p.lambda;
    }
  }
  const ContinuationSummary &newton = runs[0].continuation.summary, &chord = runs[1].continuation.summary;
  EXPECT_EQ(newton.residual_evaluations, 0);
  EXPECT_EQ(newton.chord_iterations, 0);
  EXPECT_GT(chord.chord_iterations, 0);
  // A residual without a Jacobian for every chord step (and one per corrector that ended on one).
  EXPECT_GE(chord.residual_evaluations, chord.chord_iterations);
  // Per accepted point: plain Newton factors at every iteration, chord steps mostly not.
  EXPECT_LT(static_cast<double>(chord.factorizations) / chord.points, 0.8 * newton.factorizations / newton.points);
  const auto& a = runs[0].continuation.special_points;
  const auto& b = runs[1].continuation.special_points;
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(b[i].type, a[i].type);
    EXPECT_TRUE(a[i].located && b[i].located);
    EXPECT_NEAR(b[i].lambda, a[i].lambda, 1e-8 * a[i].lambda) << a[i].type << " " << i;
  }
}

}  // namespace hbtrack_tests::file_duffing
