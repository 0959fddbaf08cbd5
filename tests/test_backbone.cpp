// Nonlinear modes by the extended periodic motion concept (`hbtrack backbone`): the Duffing
// backbone against the one-term analytic one, the NFRC peaks on the backbone, the damping
// ratio of a friction-damped mode, the EPMC Jacobian against finite differences, the CLI.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "hbtrack/analysis/backbone.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/model/damping.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_backbone {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;
namespace fs = std::filesystem;

namespace {

constexpr double kDamping = 0.05, kCubic = 0.1;

CaseDefinition example(const std::string& name, std::vector<std::string> sets = {}) {
  sets.push_back("harmonic_balance.condensation=none");
  return load_case(test::source_path("examples/" + name), sets);
}

BackboneOptions options_for(const CaseDefinition& c, double start, double end) {
  BackboneOptions o;
  o.amplitude_start = start;
  o.amplitude_end = end;
  o.continuation = c.nfrc.continuation;
  return o;
}

}  // namespace

TEST(Backbone, EpmcJacobianMatchesFiniteDifferences) {
  const CaseDefinition c = example("friction_damper.toml", {"harmonic_balance.harmonics=3"});
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  hbm.set_parameter(hbm.amplitude_parameter(), 0);
  const NormalModes modes = normal_modes(c.model.mass, c.model.stiffness);
  EpmcProblem problem(hbm, modes.shapes.col(0), 1, 1, 1, 1, 1);
  const int size = problem.size();
  VectorXd u = VectorXd::Random(size) * 0.3;
  u(size - 2) = 1.1;                       // omega
  u(size - 1) = 0.07;                      // xi
  const double lambda = std::log10(0.02);  // slipping and sticking within the period
  VectorXd r, r_lambda;
  MatrixXd J;
  problem.evaluate(u, lambda, r, &J, &r_lambda);
  auto residual = [&](const VectorXd& v) {
    VectorXd out;
    problem.evaluate(v, lambda, out, nullptr, nullptr);
    return out;
  };
  // Central differences with h = 1e-6: truncation O(h^2 f''') and round-off O(eps |r| / h).
  EXPECT_LT(test::relative_error(J, test::fd_jacobian(residual, u, 1e-6)), 1e-6);
  const VectorXd fd_lambda = test::central_difference(
      [&](double l) {
        VectorXd out;
        problem.evaluate(u, l, out, nullptr, nullptr);
        return out;
      },
      lambda, 1e-6);
  EXPECT_LT(test::relative_error(r_lambda, fd_lambda), 1e-6);
}

TEST(Backbone, DuffingFollowsTheOneTermBackboneUpToTheNeglectedHarmonics) {
  const CaseDefinition c = example("duffing.toml", {"continuation.tolerance=1e-11"});
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const BackboneResult r = compute_backbone(hbm, options_for(c, 1e-3, 2.0), c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  ASSERT_GT(r.points.size(), 10u);
  EXPECT_NEAR(r.linear_omega, 1.0, 1e-12);
  double largest_correction = 0;
  for (const BackbonePoint& p : r.points) {
    // C = c M: the negative damping cancels it exactly, whatever the amplitude.
    EXPECT_NEAR(p.xi, kDamping, 1e-8) << "a = " << p.amplitude;
    // With x = a cos + a3 cos 3t, harmonic 3 gives a3 = k3 a^3 / (4 (9 w^2 - 1)) ~ k3 a^3 / 32
    // and adds 3/4 k3 a a3 = 3/128 k3^2 a^4 to w^2 = 1 + 3/4 k3 a^2; the harmonics above 3 and
    // the rest are O(k3^3 a^6). So |w^2 - 1 - 3/4 k3 a^2| <= 2 * 3/128 k3^2 a^4 (+ the Newton
    // tolerance), and the correction is of that size, not smaller.
    const double a = p.amplitude, one_term = 1 + 0.75 * kCubic * a * a;
    const double correction = p.omega * p.omega - one_term, predicted = 3.0 / 128 * kCubic * kCubic * std::pow(a, 4);
    if (a > 1.0) continue;
    EXPECT_LE(std::abs(correction), 2 * predicted + 1e-10) << "a = " << a;
    if (a > 0.5) {
      EXPECT_NEAR(correction, predicted, 0.2 * predicted) << "a = " << a;
    }
    largest_correction = std::max(largest_correction, std::abs(correction));
  }
  EXPECT_GT(largest_correction, 1e-5) << "the harmonics above the first must show";
}

TEST(Backbone, NfrcPeaksLieOnTheDuffingBackbone) {
  const CaseDefinition c =
      example("duffing.toml", {"continuation.step=0.01", "continuation.step_max=0.01", "continuation.tolerance=1e-11"});
  for (const double forcing : {0.5, 1.0, 2.0}) {
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    hbm.set_parameter(hbm.amplitude_parameter(), forcing);
    NfrcOptions nfrc = c.nfrc;
    nfrc.omega_end = 2.0;
    const NfrcResult frc = compute_nfrc(hbm, nfrc, c.outputs);
    ASSERT_EQ(frc.continuation.summary.stop_reason, StopReason::reached_end);
    // The peak of h1 along the branch, refined by parabolas in arc length through 3 points.
    size_t best = 1;
    for (size_t i = 1; i + 1 < frc.recorded.size(); ++i)
      if (frc.recorded[i].outputs[0].h1 > frc.recorded[best].outputs[0].h1) best = i;
    const double s0 = -frc.continuation.points[best].step, s2 = frc.continuation.points[best + 1].step;
    auto vertex_and_value = [&](auto value) {
      const double y0 = value(best - 1), y1 = value(best), y2 = value(best + 1);
      const double qa = ((y2 - y1) / s2 - (y0 - y1) / s0) / (s2 - s0), qb = (y2 - y1) / s2 - qa * s2;
      return std::pair{qa, qb};
    };
    const auto [ha, hb_] = vertex_and_value([&](size_t i) { return frc.recorded[i].outputs[0].h1; });
    const double s_peak = -hb_ / (2 * ha), h1_peak = frc.recorded[best].outputs[0].h1 - hb_ * hb_ / (4 * ha);
    const auto [wa, wb] = vertex_and_value([&](size_t i) { return frc.recorded[i].omega; });
    const double omega_peak = frc.recorded[best].omega + wb * s_peak + wa * s_peak * s_peak;
    // The backbone at exactly that amplitude (M = 1: the modal amplitude is h1).
    HarmonicBalance free(c.model, c.elements, c.parameters, c.harmonic_balance);
    BackboneOptions o = options_for(c, 1e-3, h1_peak);
    const BackboneResult bb = compute_backbone(free, o, c.outputs);
    ASSERT_EQ(bb.continuation.summary.stop_reason, StopReason::reached_end);
    const double omega_bb = bb.points.back().omega;
    // One-term theory: the forced peak has 1 - w^2 + 3/4 k3 a^2 = c^2/2, the backbone
    // 1 - w^2 + 3/4 k3 a^2 = 0, so w_peak^2 = w_bb^2 - c^2/2: w_peak is below w_bb by
    // c^2 / (4 w) = 6e-4 here. Allowed: twice that, c^2 / (2 w_bb).
    EXPECT_NEAR(omega_peak, omega_bb, kDamping * kDamping / (2 * omega_bb)) << "forcing " << forcing << " a " << h1_peak;
    EXPECT_LT(omega_peak, omega_bb);
  }
}

TEST(Backbone, FrictionDampingRatioRisesThenFalls) {
  const CaseDefinition c = example("friction_damper.toml");
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const BackboneResult r = compute_backbone(hbm, options_for(c, 1e-4, 1.0), c.outputs);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  size_t peak = 0;
  for (size_t i = 0; i < r.points.size(); ++i)
    if (r.points[i].damping_ratio > r.points[peak].damping_ratio) peak = i;
  const double first = r.points.front().damping_ratio, top = r.points[peak].damping_ratio, last = r.points.back().damping_ratio;
  // Sticking at small amplitude, sliding freely at large: the peak is inside the range and well
  // above both ends (by more than a factor 2, which no discretisation error explains).
  EXPECT_GT(peak, 0u);
  EXPECT_LT(peak + 1, r.points.size());
  EXPECT_GT(top, 2 * first);
  EXPECT_GT(top, 2 * last);
  // Sliding softens the mode: omega falls from the stuck towards the free frequency.
  EXPECT_LT(r.points.back().omega, r.points.front().omega);
}

TEST(BackboneCli, WritesTheBackboneAndRejectsBadFlags) {
  const fs::path out = fs::temp_directory_path() / ("hbtrack_backbone_" + std::to_string(getpid()));
  fs::remove_all(out);
  const std::string duffing = test::source_path("examples/duffing.toml");
  const test::CliRun r = test::run_cli("backbone " + duffing + " --mode 1 --range 0.01:2 -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["verb"], "backbone");
  EXPECT_EQ(s["stop_reason"], "reached_end");
  EXPECT_EQ(s["options"]["harmonic_balance"]["condensation"], "none");
  EXPECT_NEAR(s["linear_mode"]["omega"].get<double>(), 1.0, 1e-12);
  const std::vector<std::string> header = test::csv_header(out / "branch.csv");
  ASSERT_EQ(header.size(), 4u + 2u + 8u);  // amplitude, omega, damping_ratio, xi; max, min; h0..h7
  EXPECT_EQ(header[0], "amplitude");
  EXPECT_EQ(header[2], "damping_ratio");
  EXPECT_EQ(header.back(), "h7_x");
  const std::pair<std::string, std::string> bad_flags[] = {
      {"--mode 0 --range 0.01:2", "--mode"}, {"--mode 2 --range 0.01:2", "--mode"}, {"--range 0:2", "--range"}, {"--range 2:1", "--range"}};
  for (const auto& [flags, named] : bad_flags) {
    const test::CliRun e = test::run_cli("backbone " + duffing + " " + flags + " -o " + out.string());
    EXPECT_EQ(e.exit_code, 2) << flags << ": " << e.err;
    EXPECT_NE(e.err.find(named), std::string::npos) << e.err;
  }
  fs::remove_all(out);
}

}  // namespace hbtrack_tests::file_backbone
