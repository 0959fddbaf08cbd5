// The period-doubled branch born at a period doubling (`hbtrack switch` at a PD): on the two-dof
// contact example (PD band 0.763695-0.769064, exact shooting in tests/data/shooting/two_dof_contact)
// the branch of period 2T starts at the PD, reaches the band's other PD, and its harmonics of
// omega / 2 are those time integration settles on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "hbtrack/analysis/period_doubling.hpp"
#include "hbtrack/hbm/recorded_outputs.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_period_doubling {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;
namespace fs = std::filesystem;

namespace {

// The exact PDs of the band (tests/data/shooting/two_dof_contact/special_points.json).
constexpr double kExactPd1 = 0.7636948469415585, kExactPd2 = 0.769064011738833;

// The example's NFRC from 0.62 (below the fold at 0.689, a single solution) up the resonant
// branch, through the band, stopped a little past its first PD. Hill alone decides (shooting at
// every point, the cross-check on this C0 law, costs 15 s for the whole NFRC): its PD is within
// 1.2e-4 of the exact one (docs/stability.md).
const std::vector<std::string> kWindow{"continuation.omega_start=0.62", "continuation.omega_end=0.78", "stability.cross_check=\"off\""};

struct PeriodDoubledRun {
  CaseDefinition c;
  NfrcResult nfrc;
  const SpecialPoint* pd = nullptr;
  HarmonicBalanceOptions doubled_options;
  std::unique_ptr<HarmonicBalance> hbm, doubled;
  SwitchedBranch branch;
};

// The run at the example's H = 10 (samples 256), or at `harmonics` with 32 samples per harmonic.
PeriodDoubledRun* compute_run(int harmonics) {
  auto* r = new PeriodDoubledRun;
  std::vector<std::string> overrides = kWindow;
  if (harmonics != 10) {
    overrides.push_back("harmonic_balance.harmonics=" + std::to_string(harmonics));
    overrides.push_back("harmonic_balance.samples=" + std::to_string(32 * harmonics));
  }
  r->c = load_case(test::source_path("examples/two_dof_contact.toml"), overrides);
  r->hbm = std::make_unique<HarmonicBalance>(r->c.model, r->c.elements, r->c.parameters, r->c.harmonic_balance);
  r->nfrc = compute_nfrc(*r->hbm, r->c.nfrc, r->c.outputs,
                         [](const BranchPoint& p, const RecordedPoint&, int) { return p.lambda < kExactPd1 + 2e-3; });
  for (const SpecialPoint& sp : r->nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::period_doubling && std::abs(sp.lambda - kExactPd1) < 1e-3) r->pd = &sp;
  if (!r->pd) return r;
  const auto& points = r->nfrc.continuation.points;
  const size_t i = static_cast<size_t>(r->pd->index);
  VectorXd known(r->hbm->unknowns() + 1);
  known.head(r->hbm->unknowns()) = points[i + 1].u - points[i - 1].u;
  known(r->hbm->unknowns()) = points[i + 1].lambda - points[i - 1].lambda;
  r->doubled_options = period_doubled_options(r->c.harmonic_balance);
  r->doubled = std::make_unique<HarmonicBalance>(r->c.model, r->c.elements, r->c.parameters, r->doubled_options);
  r->branch = switch_at_period_doubling(*r->doubled, r->hbm->basis(), r->c.nfrc, r->c.outputs, r->pd->u, r->pd->lambda, known);
  return r;
}

const PeriodDoubledRun& run() {
  static const PeriodDoubledRun* cached = compute_run(10);
  return *cached;
}

// Each leg's end, located where its odd harmonics vanish (a located PD special point).
const SpecialPoint* located_end(const NfrcResult& leg) {
  for (const SpecialPoint& sp : leg.continuation.special_points)
    if (sp.type == SpecialPointType::period_doubling && sp.located) return &sp;
  return nullptr;
}

// The share of the motion in the odd harmonics of omega / 2 (what a period-T orbit lacks).
double odd_share(const HarmonicBalance& doubled, const VectorXd& x) {
  const FourierBasis& b = doubled.basis();
  const int q = doubled.retained_dofs();
  double odd = 0;
  for (int c = 0; c < b.coefficients(); ++c)
    if (b.harmonic_of(c) % 2 == 1) odd += x.segment(c * q, q).squaredNorm();
  return std::sqrt(odd) / x.norm();
}

}  // namespace

TEST(PeriodDoubling, TheDoubledBasisHoldsThePeriodOneSolutionAtItsEvenHarmonics) {
  HarmonicBalanceOptions o;
  o.harmonics = 3;
  const HarmonicBalanceOptions d = period_doubled_options(o);
  EXPECT_EQ(d.subharmonic, 2);
  EXPECT_EQ(d.selected_harmonics(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  o.select({1, 3});
  EXPECT_EQ(period_doubled_options(o).selected_harmonics(), (std::vector<int>{1, 2, 3, 5, 6}));
  // The period-T solution solves the doubled system: the contact example at its PD.
  const PeriodDoubledRun& r = run();
  ASSERT_NE(r.pd, nullptr);
  const BranchPoint& p = r.nfrc.continuation.points[static_cast<size_t>(r.pd->index)];
  const VectorXd x2 = embed_in_subharmonic_basis(r.hbm->basis(), r.doubled->basis(), 2, r.hbm->retained_dofs(), p.u);
  VectorXd r1, r2;
  r.hbm->evaluate(p.u, p.lambda, r1);
  r.doubled->evaluate(x2, p.lambda, r2);
  // The same time samples (2N over 2T): the residual is the period-T one, harmonic k at 2k, to
  // round-off of the force (0.1).
  const VectorXd r1_embedded = embed_in_subharmonic_basis(r.hbm->basis(), r.doubled->basis(), 2, r.hbm->retained_dofs(), r1);
  EXPECT_LT((r2 - r1_embedded).cwiseAbs().maxCoeff(), 1e-13);
  // The same motion: the expanded harmonics at omega are those at 2 (omega / 2).
  const VectorXd f1 = r.hbm->expand(p.u, p.lambda), f2 = r.doubled->expand(x2, p.lambda);
  for (int dof = 0; dof < 2; ++dof)
    for (int k = 1; k <= r.hbm->basis().harmonics(); ++k)
      EXPECT_NEAR(harmonic_magnitude(dof_harmonics(f1, 2, 10, dof), k), harmonic_magnitude(dof_harmonics(f2, 2, 20, dof), 2 * k), 1e-12);
}

TEST(PeriodDoubling, TheDoubledBranchStartsAtThePdAndSpansTheBand) {
  const PeriodDoubledRun& r = run();
  ASSERT_NE(r.pd, nullptr) << "no PD near " << kExactPd1;
  // The NFRC's PD against the exact one (docs/stability.md: Hill alone within 1.2e-4).
  EXPECT_NEAR(r.pd->lambda, kExactPd1, 1.2e-4 * kExactPd1);
  // Both legs end where the branch rejoins the period-T one: back at this PD, and at the other.
  EXPECT_EQ(r.branch.through.continuation.summary.stop_reason, StopReason::rejoined);
  EXPECT_EQ(r.branch.away.continuation.summary.stop_reason, StopReason::rejoined);
  const SpecialPoint* low = located_end(r.branch.through);
  const SpecialPoint* high = located_end(r.branch.away);
  ASSERT_NE(low, nullptr) << "the through leg's end was not located";
  ASSERT_NE(high, nullptr) << "the away leg's end was not located";
  double widest = 0, omega_min = INFINITY, omega_max = -INFINITY;
  size_t points = 0;
  bool stable = true;
  for (const NfrcResult* leg : {&r.branch.through, &r.branch.away}) {
    for (size_t i = 0; i < leg->continuation.points.size(); ++i) {
      const BranchPoint& p = leg->continuation.points[i];
      widest = std::max(widest, odd_share(*r.doubled, p.u));
      omega_min = std::min(omega_min, p.lambda);
      omega_max = std::max(omega_max, p.lambda);
      stable = stable && leg->recorded[i].stable == 1;
      ++points;
    }
  }
  const double low_share = odd_share(*r.doubled, low->u), high_share = odd_share(*r.doubled, high->u);
  std::printf(
      "[ measured ] PD %.7f; period-doubled branch %zu points, omega %.7f .. %.7f, ends located at %.7f (odd share %.2g) .. %.7f "
      "(%.2g), widest odd share %.3g\n",
      r.pd->lambda, points, omega_min, omega_max, low->lambda, low_share, high->lambda, high_share, widest);
  // A PD bubble: from one PD to the other. The legs end at the harmonic balance's own PDs in the
  // doubled basis, a truncation of their own on this C0 law: at H = 10, 2.0e-4 and 3.7e-5 from
  // the exact ones (the NFRC's Hill PD, 9e-5 above the exact one, is a different truncation),
  // falling to 4.5e-7 and 1.6e-7 at H = 40 (next test). Compared at 2.5e-4: H = 10's measured
  // error and a quarter for the locator's 1e-3 of the bubble's width.
  EXPECT_NEAR(low->lambda, kExactPd1, 2.5e-4 * kExactPd1);
  EXPECT_NEAR(high->lambda, kExactPd2, 2.5e-4 * kExactPd2);
  // The located ends bound the branch's points: the legs run from one end to the other.
  EXPECT_LE(low->lambda, omega_min);
  EXPECT_GE(high->lambda, omega_max);
  // At both ends the period-2T part vanishes (the locator stops at 1e-3 of the largest odd
  // amplitude); in between it is 4 % of the motion.
  EXPECT_LT(low_share, 1e-2 * widest);
  EXPECT_LT(high_share, 1e-2 * widest);
  EXPECT_GT(widest, 0.02);
  // Supercritical on both sides: the period-doubled orbit is stable where the period-T one is not.
  EXPECT_TRUE(stable);
}

// The legs' located ends converge to the exact PDs as the harmonics grow: at H = 40 (1280
// samples) they are 4.5e-7 and 1.6e-7 from them (H = 20: 3.8e-6, 5.2e-7), against 2.0e-4 and
// 3.7e-5 at H = 10. Compared at 1e-6: the H = 40 truncation with a factor 2 of margin.
TEST(PeriodDoubling, TheDoubledBranchsEndsConvergeToTheExactPdsAsHarmonicsGrow) {
  static const std::unique_ptr<PeriodDoubledRun> r(compute_run(40));
  ASSERT_NE(r->pd, nullptr) << "no PD near " << kExactPd1 << " at H = 40";
  const SpecialPoint* low = located_end(r->branch.through);
  const SpecialPoint* high = located_end(r->branch.away);
  ASSERT_NE(low, nullptr);
  ASSERT_NE(high, nullptr);
  std::printf("[ measured ] H = 40: ends at %.9f (%.2g from the exact PD), %.9f (%.2g)\n", low->lambda,
              std::abs(low->lambda / kExactPd1 - 1), high->lambda, std::abs(high->lambda / kExactPd2 - 1));
  EXPECT_NEAR(low->lambda, kExactPd1, 1e-6 * kExactPd1);
  EXPECT_NEAR(high->lambda, kExactPd2, 1e-6 * kExactPd2);
}

// Time integration (Dormand-Prince, 1e-9 relative per step) from the middle of the bubble, where
// the period-doubled orbit is farthest from the period-T one: after 200 forcing periods the
// motion repeats every 2T, not every T, and its harmonics of omega / 2 are the branch's.
TEST(PeriodDoubling, TimeIntegrationSettlesOnThePeriodDoubledOrbit) {
  const PeriodDoubledRun& r = run();
  ASSERT_NE(r.pd, nullptr);
  const NfrcResult& leg = r.branch.away;  // from the middle of the band to its upper PD
  ASSERT_FALSE(leg.continuation.points.empty());
  size_t widest = 0;
  for (size_t i = 0; i < leg.continuation.points.size(); ++i)
    if (odd_share(*r.doubled, leg.continuation.points[i].u) > odd_share(*r.doubled, leg.continuation.points[widest].u)) widest = i;
  const BranchPoint& p = leg.continuation.points[widest];
  EXPECT_EQ(leg.recorded[widest].stable, 1) << "the period-doubled orbit in the band is stable";
  const int n = 2, h = r.doubled->basis().harmonics(), samples = 256;
  const VectorXd full = r.doubled->expand(p.u, p.lambda);
  EquationOfMotion eom(r.c.model, r.c.elements, r.doubled->parameters(), p.lambda);
  DormandPrinceOptions options;
  options.samples_per_period = samples;
  DormandPrinceIntegrator integrator(eom, options);
  integrator.start(state_from_harmonics(full, n, h, r.doubled->fundamental(p.lambda)));
  constexpr int kPeriods = 200;  // even: the last two start where the harmonic balance's tau = 0
  MatrixXd last(2 * samples, n);
  for (int period = 0; period < kPeriods; ++period) {
    const int offset = (period % 2) * samples;
    ASSERT_TRUE(integrator.advance_period([&](int i, const MotionState& s) { last.row(offset + i) = s.x.transpose(); }))
        << integrator.failure().message;
  }
  // The last two forcing periods = one period of the branch: their harmonics of omega / 2.
  const FourierBasis basis(h, 2 * samples);
  double worst = 0, half_error = 0, repeat = 0, scale = 0;
  for (int dof = 0; dof < n; ++dof) {
    const VectorXd simulated = basis.analysis() * last.col(dof);
    const VectorXd balanced = dof_harmonics(full, n, h, dof);
    scale = std::max(scale, simulated.cwiseAbs().maxCoeff());
    worst = std::max(worst, (simulated - balanced).cwiseAbs().maxCoeff());
    half_error = std::max(half_error,
                          std::abs(harmonic_magnitude(simulated, 1) - harmonic_magnitude(balanced, 1)) / harmonic_magnitude(simulated, 1));
    repeat = std::max(repeat, (last.col(dof).head(samples) - last.col(dof).tail(samples)).cwiseAbs().maxCoeff());
  }
  std::printf(
      "[ measured ] omega %.6f: harmonics of omega/2, worst %.2e of the largest; omega/2 magnitude %.2e relative; T-repeat %.3g of %.3g\n",
      p.lambda, worst / scale, half_error, repeat, scale);
  EXPECT_GT(repeat, 0.05 * scale) << "period 2T, not T";
  // Every harmonic to 2e-3 of the largest: the truncation error of H = 10 (20 halves) on this C0
  // law (measured 7.6e-4). The omega / 2 harmonic to 5 % of itself (measured 2.4 %): its square
  // grows as (omega - w1)(w2 - omega) across the band, so the harmonic balance's PDs w1, w2,
  // 9.0e-5 and 2.9e-5 off the exact ones, put it off by (9.0e-5 / (omega - w1) + 2.9e-5 /
  // (w2 - omega)) / 2 = 2.1 % in the middle of the band.
  EXPECT_LT(worst, 2e-3 * scale);
  EXPECT_LT(half_error, 5e-2);
}

TEST(PeriodDoubling, TheCliSwitchesAtAPdOntoTheBranchAtHalfTheFrequency) {
  const fs::path frc = fs::temp_directory_path() / ("hbtrack_pd_frc_" + std::to_string(getpid()));
  const fs::path out = fs::temp_directory_path() / ("hbtrack_pd_" + std::to_string(getpid()));
  fs::remove_all(frc);
  fs::remove_all(out);
  const std::string contact = test::source_path("examples/two_dof_contact.toml");
  // The NFRC up to a little past the PD only (the switch runs in the case's window, 0.3 to 2).
  const std::string window =
      " --set continuation.omega_start=0.62 --set continuation.omega_end=0.7665 --set 'stability.cross_check=\"off\"'";
  ASSERT_EQ(test::run_cli("frc " + contact + window + " -o " + frc.string() + " -q").exit_code, 0);
  const nlohmann::json f = nlohmann::json::parse(std::ifstream(frc / "summary.json"));
  int pd = 0;
  for (size_t k = 0; k < f["special_points"].size(); ++k)
    if (f["special_points"][k]["type"] == "PD" && std::abs(f["special_points"][k]["omega"].get<double>() - kExactPd1) < 1e-3)
      pd = static_cast<int>(k) + 1;
  ASSERT_GT(pd, 0);
  const test::CliRun r =
      test::run_cli("switch " + contact + " --from " + frc.string() + " --point " + std::to_string(pd) + " -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["stop_reason"], "completed");
  EXPECT_EQ(s["legs"][0]["stop_reason"], "rejoined");  // back at the PD
  EXPECT_EQ(s["legs"][1]["stop_reason"], "rejoined");  // at the band's other PD
  EXPECT_EQ(s["options"]["switch"]["type"], "PD");
  EXPECT_EQ(s["options"]["harmonic_balance"]["subharmonic"], 2);
  EXPECT_EQ(s["options"]["harmonic_balance"]["unknowns"], 41);  // 0..20 halves of omega on the contact dof
  const std::vector<std::string> header = test::csv_header(out / "branch.csv");
  for (const char* column : {"max_x2", "h1_x2", "h0.5_x2", "h1.5_x2", "h10_x2", "phase0.5_x2"})
    EXPECT_NE(std::find(header.begin(), header.end(), column), header.end()) << column;
  double widest = 0;
  for (const auto& row : test::csv_records(out / "branch.csv")) widest = std::max(widest, row.at("h0.5_x2"));
  EXPECT_GT(widest, 0.01);  // the period-doubled part of the motion (measured below)
  std::printf("[ measured ] switch: %d points, largest |h0.5_x2| %.4f, %zu special points\n", s["points"].get<int>(), widest,
              s["special_points"].size());
  fs::remove_all(frc);
  fs::remove_all(out);
}

}  // namespace hbtrack_tests::file_period_doubling
