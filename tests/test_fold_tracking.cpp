// Limit-point tracking: the fold systems' Jacobians against finite differences, the Duffing
// fold curve in the forcing amplitude against separately computed NFRCs and its cusp, the
// extended and minimally augmented systems against each other, and closure of a loop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_fold_tracking {

using namespace hbtrack;

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct Duffing {
  CaseDefinition c;
  HarmonicBalance hbm;
  int amplitude;
  FoldScales scales;
  explicit Duffing(double amplitude_value = 1.0)
      : c(load_case(test::source_path("examples/duffing.toml"), {"amplitude=" + std::to_string(amplitude_value)})),
        hbm(c.model, c.elements, c.parameters, c.harmonic_balance),
        amplitude(hbm.amplitude_parameter()) {
    const double reference = automatic_length_scale(hbm, c.nfrc.omega_start, c.nfrc.omega_end);
    scales = {0.01 * reference, std::abs(c.nfrc.omega_end - c.nfrc.omega_start), force_scale(hbm, reference), 1.0};
  }
  // Located limit points of the NFRC at the current amplitude: (omega, state).
  std::vector<SpecialPoint> limit_points() {
    NfrcOptions o = c.nfrc;
    o.stability.method = StabilityMethod::none;
    std::vector<SpecialPoint> lps;
    for (const SpecialPoint& sp : compute_nfrc(hbm, o, {}).continuation.special_points)
      if (sp.type == SpecialPointType::limit_point && sp.located) lps.push_back(sp);
    return lps;
  }
  FoldTrackingResult track(const SpecialPoint& lp, double lo, double hi, const std::string& method) {
    FoldTrackingOptions o;
    o.method = parse_tracking_method(method);
    o.parameter_min = lo;
    o.parameter_max = hi;
    o.continuation = c.nfrc.continuation;
    FoldScales s = scales;
    s.parameter = hi - lo;
    return track_fold(hbm, amplitude, lp.u, lp.lambda, s, o, {});
  }
};

// Last point of each leg: the curve's two ends, landed on the range's bounds.
std::vector<FoldCurvePoint> leg_ends(const FoldTrackingResult& r) {
  std::vector<FoldCurvePoint> ends;
  for (size_t i = 0; i < r.points.size(); ++i)
    if (i + 1 == r.points.size() || r.points[i + 1].leg != r.points[i].leg) ends.push_back(r.points[i]);
  return ends;
}

const FoldScales kUnitScales{0.1, 1.0, 0.1, 1.0};

CaseDefinition two_dof_contact_case() {
  return load_case(test::source_path("examples/two_dof_contact.toml"), {"harmonic_balance.harmonics=3"});
}

// Approximate right and left null vectors of R_x at (x, omega): the fold systems' borders.
void null_vectors_at(HarmonicBalance& hbm, const VectorXd& x, double omega, VectorXd& right, VectorXd& left) {
  VectorXd r;
  MatrixXd j;
  hbm.evaluate(x, omega, r, &j, nullptr);
  approximate_null_vectors(j, right, left);
}

// Both fold systems' Jacobians and parameter derivatives against central differences of their
// residuals (borders fixed), at (x, omega) with borders from R_x's approximate null vectors.
void expect_fold_jacobians_match_finite_differences(HarmonicBalance& hbm, const VectorXd& x, double omega,
                                                    const std::vector<std::string>& parameters) {
  VectorXd right, left;
  null_vectors_at(hbm, x, omega, right, left);
  const FoldScales& scales = kUnitScales;
  for (const std::string& name : parameters) {
    const int p = hbm.parameters().find(name);
    const double gamma = hbm.parameters().value(p);
    BorderedFoldSystem bordered(hbm, p, scales);
    ExtendedFoldSystem extended(hbm, p, scales);
    for (FoldSystem* system : {static_cast<FoldSystem*>(&bordered), static_cast<FoldSystem*>(&extended)}) {
      const VectorXd u = system->start(x, omega, right, left);
      VectorXd r0, r_gamma;
      MatrixXd jac;
      system->evaluate(u, gamma, r0, &jac, &r_gamma);
      // Central differences of the residual (borders fixed): step 1e-6 relative.
      auto residual = [&](const VectorXd& v, double g) {
        VectorXd out;
        system->evaluate(v, g, out, nullptr, nullptr);
        return out;
      };
      const MatrixXd fd = test::fd_jacobian([&](const VectorXd& v) { return residual(v, gamma); }, u, 1e-6);
      const VectorXd fd_gamma = test::central_difference([&](double g) { return residual(u, g); }, gamma, 1e-6 * std::abs(gamma));
      // The analytic part is exact; the second derivatives come from one forward difference with
      // a relative step 1e-6: errors of order 1e-6 of the largest entry.
      EXPECT_LT(test::relative_error(jac, fd), 1e-4) << system->method() << " " << name;
      EXPECT_LT(test::relative_error(r_gamma, fd_gamma), 1e-4) << system->method() << " " << name;
    }
  }
}

TEST(FoldSystems, JacobiansMatchFiniteDifferencesForEveryParameterKind) {
  // Two-dof contact: amplitude (linear, no x dependence) and clearance (inside the contact law).
  CaseDefinition c = two_dof_contact_case();
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const double omega = 1.1;
  expect_fold_jacobians_match_finite_differences(hbm, hbm.linear_solution(omega) * 1.3, omega, {"amplitude", "clearance"});
}

TEST(FoldSystems, JacobiansMatchFiniteDifferencesWithFrictionAndLanczosFiltering) {
  // Velocity-dependent forces (friction on the tip contact and a tanh friction element) and
  // Lanczos factors: the bordered system's products with w go through all of them.
  test::ContactPoint p = test::contact_point_in_contact();
  expect_fold_jacobians_match_finite_differences(p.hbm, p.x, p.omega, {"amplitude", "mu"});
}

TEST(FoldSystems, JacobiansMatchFiniteDifferencesWithAForcingGrowingWithOmega) {
  // An unbalance-like forcing, (omega / 1.2)^2 f: R_omega carries its derivative, which both
  // fold systems' omega column must see (and the amplitude's derivative its factor).
  CaseDefinition c = two_dof_contact_case();
  c.model.forcing_growth = {2.0, 1.2};
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const double omega = 1.1;
  expect_fold_jacobians_match_finite_differences(hbm, hbm.linear_solution(omega) * 1.3, omega, {"amplitude", "clearance"});
}

TEST(FoldSystems, BorderedResidualFromKeptFactorsEqualsAFreshFactorization) {
  // A residual without the Jacobian (a chord iteration) refines the bordered null vector from the
  // factors of the last full evaluation; a fresh system factors the same matrix anew.
  CaseDefinition c = two_dof_contact_case();
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const double omega = 1.1;
  const VectorXd x = hbm.linear_solution(omega) * 1.3;
  VectorXd right, left;
  null_vectors_at(hbm, x, omega, right, left);
  const int p = hbm.parameters().find("clearance");
  const double gamma = hbm.parameters().value(p);
  BorderedFoldSystem kept(hbm, p, kUnitScales), fresh(hbm, p, kUnitScales);
  const VectorXd u = kept.start(x, omega, right, left);
  fresh.start(x, omega, right, left);
  VectorXd r_full, r_gamma;
  MatrixXd jac;
  kept.evaluate(u, gamma, r_full, &jac, &r_gamma);
  // A corrector's step away: 1e-3 relative in every unknown.
  const VectorXd moved =
      u + 1e-3 * u.cwiseAbs().cwiseMax(1e-3 * u.cwiseAbs().maxCoeff()).cwiseProduct(VectorXd::LinSpaced(u.size(), -1.0, 1.0));
  VectorXd r_kept, r_fresh;
  kept.evaluate(moved, gamma, r_kept, nullptr, nullptr);
  fresh.evaluate(moved, gamma, r_fresh, nullptr, nullptr);
  EXPECT_EQ(kept.border_factorizations(), 1);  // the full evaluation's only
  EXPECT_EQ(fresh.border_factorizations(), 1);
  // Both solve the same bordered system to a backward error of 1e-13 (the refinement's stop,
  // what an LU attains); its condition number here is below 1e3: 1e-10 relative.
  EXPECT_LE((r_kept - r_fresh).lpNorm<Eigen::Infinity>(), 1e-10 * r_fresh.lpNorm<Eigen::Infinity>());
  EXPECT_NE(r_kept(r_kept.size() - 1), r_full(r_full.size() - 1));  // g moved with the point
}

TEST(FoldTracking, DuffingCurvePassesThroughTheLimitPointsOfSeparateNfrcsAndEndsAtTheCusp) {
  Duffing d(1.0);
  const std::vector<SpecialPoint> lps = d.limit_points();
  ASSERT_EQ(lps.size(), 2u);
  // From the upper LP, down through the cusp and up the lower LP's curve, both legs to 1.8.
  const FoldTrackingResult r = d.track(lps[0], 0.25, 1.8, "bordered");
  ASSERT_TRUE(r.success()) << r.legs.back().stop_reason;
  ASSERT_EQ(r.extrema.size(), 1u);
  const FoldExtremum& cusp = r.extrema[0];
  EXPECT_EQ(cusp.type, CurveExtremumType::parameter_min);
  EXPECT_TRUE(cusp.located);
  // The curve's two ends at amplitude 1.8 are the two LPs of the NFRC computed at 1.8.
  Duffing at(1.8);
  const std::vector<SpecialPoint> separate = at.limit_points();
  ASSERT_EQ(separate.size(), 2u);
  const std::vector<FoldCurvePoint> ends = leg_ends(r);
  ASSERT_EQ(ends.size(), 2u);
  for (const FoldCurvePoint& end : ends) {
    EXPECT_NEAR(end.parameter, 1.8, 1e-12);
    double nearest = 1e300;
    for (const SpecialPoint& sp : separate) nearest = std::min(nearest, std::abs(end.omega - sp.lambda) / sp.lambda);
    EXPECT_LT(nearest, 1e-6) << "end at omega " << end.omega;
  }
  EXPECT_GT(std::abs(ends[0].omega - ends[1].omega), 0.05);  // one end on each LP
  // Two more amplitudes: 0.6 on the upper LP's leg, and 1.4 (every curve point is an LP).
  for (double a : {0.6, 1.4}) {
    Duffing other(a);
    const std::vector<SpecialPoint> lp_a = other.limit_points();
    ASSERT_EQ(lp_a.size(), 2u);
    const FoldTrackingResult to_a = d.track(lps[0], std::min(a, 1.0), std::max(a, 1.0) + (a > 1.0 ? 0.0 : 0.5), "bordered");
    bool matched = false;
    for (const FoldCurvePoint& end : leg_ends(to_a))
      if (std::abs(end.parameter - a) < 1e-12)
        for (const SpecialPoint& sp : lp_a) matched = matched || std::abs(end.omega - sp.lambda) / sp.lambda < 1e-6;
    EXPECT_TRUE(matched) << "amplitude " << a;
  }
  // The cusp: two LPs just above its amplitude, none just below.
  Duffing above(cusp.parameter * 1.01), below(cusp.parameter * 0.99);
  const auto above_lps = above.limit_points();
  EXPECT_EQ(above_lps.size(), 2u);
  EXPECT_TRUE(below.limit_points().empty());
  for (const SpecialPoint& sp : above_lps) EXPECT_NEAR(sp.lambda, cusp.omega, 0.02 * cusp.omega);
}

TEST(FoldTracking, ExtendedAndMinimallyAugmentedSystemsGiveTheSameCurve) {
  Duffing d(1.0);
  const std::vector<SpecialPoint> lps = d.limit_points();
  ASSERT_EQ(lps.size(), 2u);
  const FoldTrackingResult bordered = d.track(lps[1], 0.25, 2.0, "bordered");
  const FoldTrackingResult extended = d.track(lps[1], 0.25, 2.0, "extended");
  ASSERT_TRUE(bordered.success());
  ASSERT_TRUE(extended.success());
  ASSERT_EQ(bordered.extrema.size(), 1u);
  ASSERT_EQ(extended.extrema.size(), 1u);
  // Same cusp and same ends (each solved to the Newton tolerance, 1e-9 of the forcing).
  EXPECT_LT(std::abs(bordered.extrema[0].parameter - extended.extrema[0].parameter) / bordered.extrema[0].parameter, 1e-8);
  EXPECT_LT(std::abs(bordered.extrema[0].omega - extended.extrema[0].omega) / bordered.extrema[0].omega, 1e-8);
  const auto ends_b = leg_ends(bordered), ends_e = leg_ends(extended);
  ASSERT_EQ(ends_b.size(), ends_e.size());
  for (size_t i = 0; i < ends_b.size(); ++i) {
    EXPECT_EQ(ends_b[i].parameter, ends_e[i].parameter);
    EXPECT_LT(std::abs(ends_b[i].omega - ends_e[i].omega) / ends_b[i].omega, 1e-8);
    EXPECT_LT((ends_b[i].x - ends_e[i].x).cwiseAbs().maxCoeff() / ends_b[i].x.cwiseAbs().maxCoeff(), 1e-8);
  }
}

// R(u, lambda) = u^2 + lambda^2 - 1: a circle, which the continuation must close.
class Circle final : public ContinuationProblem {
 public:
  int size() const override { return 1; }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* j, VectorXd* r_lambda) override {
    r = VectorXd::Constant(1, u(0) * u(0) + lambda * lambda - 1.0);
    if (j) *j = MatrixXd::Constant(1, 1, 2.0 * u(0));
    if (r_lambda) *r_lambda = VectorXd::Constant(1, 2.0 * lambda);
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(1); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
};

TEST(Continuation, ClosedBranchStopsBackOnItsFirstPoint) {
  Circle circle;
  ContinuationOptions o;
  o.step = o.step_max = 0.05;
  const ParameterWindow window{-2.0, 2.0, 1, true};
  const ContinuationResult r = continue_within(circle, VectorXd::Constant(1, 0.8), 0.6, window, o);
  ASSERT_EQ(r.summary.stop_reason, StopReason::closed);
  EXPECT_TRUE(r.success());
  // Once round: arc 2 pi in steps of at most 0.05, last point = first point.
  double length = 0;
  for (const BranchPoint& p : r.points) length += p.step;
  EXPECT_NEAR(length, 2 * M_PI, 0.01);
  EXPECT_EQ(r.points.back().u, r.points.front().u);
  EXPECT_EQ(r.points.back().lambda, r.points.front().lambda);
  // Without the request it runs into the window instead (here it never leaves: max_points).
  o.max_points = 300;
  const ContinuationResult open = continue_within(circle, VectorXd::Constant(1, 0.8), 0.6, {-2.0, 2.0, 1, false}, o);
  EXPECT_EQ(open.summary.stop_reason, StopReason::max_points);
}

}  // namespace

}  // namespace hbtrack_tests::file_fold_tracking
