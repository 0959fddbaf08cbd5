// Neimark-Sacker and period-doubling tracking on Hill's pencil: the system's Jacobian against
// finite differences; the NS curve of the nonlinear absorber (examples/nltva.toml) and the PD
// curve of the two-dof contact example in the forcing amplitude against the NS (PD) points of
// NFRCs computed separately at other amplitudes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "hbtrack/analysis/critical_exponent_system.hpp"
#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_ns_tracking {

using namespace hbtrack;

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct Absorber {
  CaseDefinition c;
  HarmonicBalance hbm;
  int amplitude;
  FoldScales scales;
  explicit Absorber(double amplitude_value)
      : c(load_case(test::source_path("examples/nltva.toml"), {"amplitude=" + std::to_string(amplitude_value)})),
        hbm(c.model, c.elements, c.parameters, c.harmonic_balance),
        amplitude(hbm.amplitude_parameter()),
        scales(tracking_scales(hbm, c.nfrc, 1.0)) {}  // the units `hbtrack track` uses
  // The NS curve from NS point `start` within A in [0.05, 0.35], in the units `hbtrack track` uses.
  FoldTrackingResult track_ns(const SpecialPoint& start, const FoldTrackingRestart& restart = {}) const {
    FoldTrackingOptions o;
    o.tracked = TrackedPoint::neimark_sacker;
    o.parameter_min = 0.05;
    o.parameter_max = 0.35;
    o.continuation = c.nfrc.continuation;
    return track_fold(hbm, amplitude, start.u, start.lambda, ns_scales(), o, {}, {}, restart);
  }
  FoldScales ns_scales() const {
    FoldScales s = scales;
    s.parameter = 0.35 - 0.05;
    return s;
  }
  // Located NS points of the NFRC (with Hill's stability, the case's default), in increasing omega.
  std::vector<SpecialPoint> ns_points() {
    std::vector<SpecialPoint> ns;
    for (const SpecialPoint& sp : compute_nfrc(hbm, c.nfrc, {}).continuation.special_points)
      if (sp.type == SpecialPointType::neimark_sacker && sp.located) ns.push_back(sp);
    std::sort(ns.begin(), ns.end(), [](const SpecialPoint& a, const SpecialPoint& b) { return a.lambda < b.lambda; });
    return ns;
  }
};

// The NS (PD) point of the curve at amplitude `value`, between curve points a and b:
// interpolated linearly in the amplitude (x, omega and the exponent's frequency), then Newton on
// the system at that amplitude.
double omega_on_curve(const HarmonicBalance& hbm, const FoldScales& scales, double tolerance, CriticalExponent kind,
                      const FoldCurvePoint& a, const FoldCurvePoint& b, double value, bool& converged) {
  const double f = (value - a.parameter) / (b.parameter - a.parameter);
  const int amplitude = hbm.amplitude_parameter();
  const HarmonicBalance at = hbm.with_parameter(amplitude, value);
  CriticalExponentSystem system(at, amplitude, scales, kind);
  VectorXd u = system.start_at_frequency(a.x + f * (b.x - a.x), a.omega + f * (b.omega - a.omega), value,
                                         a.critical_frequency + f * (b.critical_frequency - a.critical_frequency));
  converged = newton_at_fixed_parameter(system, u, value, tolerance, 20) >= 0;
  return system.omega(u);
}

// Every crossing of the curve `r` with the amplitude `value`, refined, against the nearest of
// the NFRC's points `separate` there: relative distances in omega, one per crossing.
std::vector<double> crossing_distances(const FoldTrackingResult& r, const HarmonicBalance& hbm, const FoldScales& scales, double tolerance,
                                       CriticalExponent kind, double value, const std::vector<SpecialPoint>& separate) {
  std::vector<double> out;
  for (size_t i = 0; i + 1 < r.points.size(); ++i) {
    const FoldCurvePoint &a = r.points[i], &b = r.points[i + 1];
    if (a.leg != b.leg || !((a.parameter - value) * (b.parameter - value) < 0)) continue;
    bool converged = false;
    const double omega = omega_on_curve(hbm, scales, tolerance, kind, a, b, value, converged);
    EXPECT_TRUE(converged) << "A = " << value;
    double nearest = 1e300;
    for (const SpecialPoint& sp : separate) nearest = std::min(nearest, std::abs(omega - sp.lambda) / sp.lambda);
    out.push_back(nearest);
  }
  return out;
}

void record_distances(double value, const std::vector<double>& distances) {
  for (size_t k = 0; k < distances.size(); ++k) {
    char measured[32];
    std::snprintf(measured, sizeof measured, "%.2e", distances[k]);
    ::testing::Test::RecordProperty("A_" + std::to_string(value) + "_" + std::to_string(k + 1), measured);
  }
}

}  // namespace

TEST(NeimarkSackerSystem, JacobianMatchesFiniteDifferencesWithFrictionAndAParameterInTheLaw) {
  // Velocity-dependent forces (friction) and a parameter inside a law (mu): every part of
  // w^H A_z v. The borders come from the pencil at the exponent nearest the axis among the
  // complex ones, wherever the point: a Jacobian check needs no NS point.
  test::ContactPoint point = test::contact_point_in_contact();
  HarmonicBalance& hbm = point.hbm;
  const VectorXd& x = point.x;
  const double omega = point.omega;
  for (const std::string name : {"amplitude", "mu"}) {
    const int p = hbm.parameters().find(name);
    const double gamma = hbm.parameters().value(p);
    CriticalExponentSystem system(hbm, p, {0.1, 1.0, 0.1, 1.0}, CriticalExponent::neimark_sacker);
    const VectorXd u = system.start_at(x, omega, gamma);
    VectorXd r0, r_gamma;
    MatrixXd jac;
    system.evaluate(u, gamma, r0, &jac, &r_gamma);
    auto residual = [&](const VectorXd& v, double g) {
      VectorXd out;
      system.evaluate(v, g, out, nullptr, nullptr);
      return out;
    };
    const MatrixXd fd = test::fd_jacobian([&](const VectorXd& v) { return residual(v, gamma); }, u, 1e-6);
    const VectorXd fd_gamma = test::central_difference([&](double g) { return residual(u, g); }, gamma, 1e-6 * std::abs(gamma));
    // The g rows come from one forward difference of w^H A v with a relative step 1e-6 (A_nu
    // exactly): errors of order 1e-6 of the largest entry.
    EXPECT_LT(test::relative_error(jac, fd), 1e-4) << name;
    EXPECT_LT(test::relative_error(r_gamma, fd_gamma), 1e-4) << name;
    EXPECT_GT(jac.bottomRows(2).norm(), 1e-3 * jac.norm());  // the g rows are not a vacuous match
  }
}

TEST(NeimarkSackerTracking, AbsorberCurvePassesThroughTheNsPointsOfSeparateNfrcs) {
  Absorber d(0.12);
  const std::vector<SpecialPoint> start = d.ns_points();
  ASSERT_EQ(start.size(), 2u);  // 1.1096 and 1.2247 rad/s
  const FoldTrackingResult r = d.track_ns(start[0]);
  const FoldScales s = d.ns_scales();
  ASSERT_TRUE(r.success()) << to_string(r.stop_reason());
  // Both legs end where the NS frequency vanishes (the NS curve meets the fold curve), one on
  // each side of the curve's minimum in amplitude, where the unstable band is born.
  ASSERT_EQ(r.legs.size(), 2u);
  for (const ContinuationSummary& leg : r.legs) EXPECT_EQ(leg.stop_reason, StopReason::strong_resonance);
  int minima = 0, resonances = 0;
  for (const FoldExtremum& e : r.extrema) {
    EXPECT_TRUE(e.located) << e.type;
    if (e.type == CurveExtremumType::parameter_min) {
      ++minima;
      EXPECT_NEAR(e.parameter, 0.0988, 1e-4);
      EXPECT_NEAR(e.omega, 1.1353, 1e-4);
      EXPECT_GT(e.critical_frequency, 0.05);  // a genuine NS point, multipliers well off +1
    }
    if (e.type == CurveExtremumType::resonance_1_1) {
      ++resonances;
      // Located on the zero of sin(pi nu / w): nu to the secant's 1e-12 of the bracket.
      EXPECT_LT(e.critical_frequency, 1e-8);
    }
  }
  EXPECT_EQ(minima, 1);
  EXPECT_EQ(resonances, 2);
  // The curve's NS frequency at the start is Hill's: the multiplier's angle there over the period.
  EXPECT_NEAR(r.points.front().critical_frequency, 0.0977, 1e-4);
  // NFRCs at three amplitudes: every crossing of the curve with the amplitude is an NS point of
  // the NFRC there, to 1e-5 relative in omega. The NS points of an NFRC the curve does not cross
  // (near 1.78 rad/s at A = 0.2: the isola's band) belong to another NS curve.
  for (double value : {0.105, 0.13, 0.2}) {
    Absorber other(value);
    const std::vector<double> distances =
        crossing_distances(r, d.hbm, s, d.c.nfrc.continuation.tolerance, CriticalExponent::neimark_sacker, value, other.ns_points());
    EXPECT_EQ(distances.size(), value < 0.149 ? 2u : 1u) << "A = " << value;  // two NS points below the curve's 1:1 end at 0.149
    // The NFRC locates its NS points to 1e-12 of a step on Hill's test function, this system
    // its own to the continuation's tolerance: both far below the 1e-5.
    for (double distance : distances) EXPECT_LT(distance, 1e-5) << "A = " << value;
    record_distances(value, distances);
  }
}

TEST(NeimarkSackerTracking, ARunResumedFromACheckpointRepeatsTheCurve) {
  // The checkpoint holds the complex borders as four real vectors; resumed in leg 1 and in leg 2
  // (after leg 1 ended on its resonance), the run gives the uninterrupted run's points bit for
  // bit, and the same extrema.
  Absorber d(0.12);
  const std::vector<SpecialPoint> start = d.ns_points();
  ASSERT_FALSE(start.empty());
  std::vector<FoldTrackingState> saved;
  FoldTrackingRestart keep;
  keep.on_state = [&](const FoldTrackingState& state) {
    const bool first_in_leg = saved.empty() || saved.back().leg != state.leg;
    if ((state.curve_points == 10 || first_in_leg) && state.curve_points > 0) saved.push_back(state);
  };
  const FoldTrackingResult full = d.track_ns(start[0], keep);
  ASSERT_TRUE(full.success());
  ASSERT_GE(saved.size(), 2u);
  ASSERT_EQ(saved.front().leg, 1);
  ASSERT_EQ(saved.back().leg, 2);
  for (const FoldTrackingState& state : {saved.front(), saved.back()}) {
    FoldTrackingRestart resume;
    resume.resume_from = &state;
    const FoldTrackingResult r = d.track_ns(start[0], resume);
    ASSERT_TRUE(r.success()) << "leg " << state.leg;
    ASSERT_EQ(r.curve_points(), full.curve_points()) << "leg " << state.leg;
    for (size_t i = 0; i < r.points.size(); ++i) {
      const FoldCurvePoint& a = r.points[i];
      const FoldCurvePoint& b = full.points[static_cast<size_t>(r.points_before) + i];
      EXPECT_EQ(a.omega, b.omega);
      EXPECT_EQ(a.parameter, b.parameter);
      EXPECT_EQ(a.critical_frequency, b.critical_frequency);
    }
    ASSERT_EQ(r.extrema.size(), full.extrema.size()) << "leg " << state.leg;
    for (size_t i = 0; i < r.extrema.size(); ++i) EXPECT_EQ(r.extrema[i].type, full.extrema[i].type);
  }
}

// The two-dof example with the smooth contact of docs/examples.md (sqrt law, width 0.05,
// stiffness 10) at H = 10: a PD band 1.60804-1.62568 rad/s at A = 1, on the NFRC from 1.5. Its
// unilateral spring (penalty, C0) would not do: the pencil holds the Jacobian, only C0 in x on
// that law, and the PD curve has corners the continuation stalls on.
const std::vector<std::string> kPdWindow{"elements[0].type=\"regularized_contact\"",
                                         "elements[0].law=\"sqrt\"",
                                         "elements[0].width=0.05",
                                         "elements[0].stiffness=10",
                                         "continuation.omega_start=1.5",
                                         "continuation.omega_end=1.7",
                                         "stability.cross_check=\"off\""};

std::vector<SpecialPoint> band_pds(const CaseDefinition& c, HarmonicBalance& hbm) {
  std::vector<SpecialPoint> pds;
  for (const SpecialPoint& sp : compute_nfrc(hbm, c.nfrc, {}).continuation.special_points)
    if (sp.type == SpecialPointType::period_doubling && sp.located) pds.push_back(sp);
  return pds;
}

TEST(PeriodDoublingTracking, ContactBandCurvePassesThroughThePdPointsOfSeparateNfrcs) {
  const CaseDefinition c = load_case(test::source_path("examples/two_dof_contact.toml"), kPdWindow);
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const std::vector<SpecialPoint> start = band_pds(c, hbm);
  ASSERT_EQ(start.size(), 2u);
  const FoldScales s = tracking_scales(hbm, c.nfrc, 0.4);
  FoldTrackingOptions o;
  o.tracked = TrackedPoint::period_doubling;
  o.parameter_min = 0.9;
  o.parameter_max = 1.3;
  o.continuation = c.nfrc.continuation;
  const FoldTrackingResult r = track_fold(hbm, hbm.amplitude_parameter(), start[0].u, start[0].lambda, s, o, {});
  ASSERT_TRUE(r.success()) << to_string(r.stop_reason());
  // One minimum in A: where the band is born (both PDs of the band lie on this one curve).
  ASSERT_EQ(r.extrema.size(), 1u);
  EXPECT_EQ(r.extrema[0].type, CurveExtremumType::parameter_min);
  EXPECT_NEAR(r.extrema[0].parameter, 0.9482, 1e-3);
  EXPECT_NEAR(r.extrema[0].omega, 1.6170, 1e-3);
  // The PD exponent's frequency is w/2 up to Hill's truncation (3e-6 rad/s here).
  for (const FoldCurvePoint& p : r.points) EXPECT_NEAR(p.critical_frequency, 0.5 * p.omega, 1e-3 * p.omega);
  for (double value : {0.98, 1.2}) {
    std::vector<std::string> settings = kPdWindow;
    settings.push_back("amplitude=" + std::to_string(value));
    const CaseDefinition other = load_case(test::source_path("examples/two_dof_contact.toml"), settings);
    HarmonicBalance other_hbm(other.model, other.elements, other.parameters, other.harmonic_balance);
    const std::vector<double> distances =
        crossing_distances(r, hbm, s, c.nfrc.continuation.tolerance, CriticalExponent::period_doubling, value, band_pds(other, other_hbm));
    EXPECT_EQ(distances.size(), 2u) << "A = " << value;  // both ends of the band
    for (double distance : distances) EXPECT_LT(distance, 1e-5) << "A = " << value;
    record_distances(value, distances);
  }
}

}  // namespace hbtrack_tests::file_ns_tracking
