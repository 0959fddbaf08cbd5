// The quasi-periodic response past a Neimark-Sacker point (analysis/torus_branch.hpp) on the
// nonlinear absorber (examples/nltva.toml, NS points at 1.1096 and 1.2247 rad/s): the torus
// residual's analytic Jacobian against central differences (cubic springs; a velocity-dependent
// law), and the branch's ends at the two NS points. The comparison with time integration is
// tests/test_torus_cli.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/analysis/torus_branch.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_torus {

using namespace hbtrack;

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct Absorber {
  CaseDefinition c = load_case(test::source_path("examples/nltva.toml"));
  HarmonicBalance hbm{c.model, c.elements, c.parameters, c.harmonic_balance};
  FoldScales scales = tracking_scales(hbm, c.nfrc, 0.3);  // the units `hbtrack torus --range 1.0:1.3` uses
  // Located NS points of the NFRC, in increasing omega.
  std::vector<SpecialPoint> ns_points() {
    std::vector<SpecialPoint> ns;
    for (const SpecialPoint& sp : compute_nfrc(hbm, c.nfrc, {}).continuation.special_points)
      if (sp.type == SpecialPointType::neimark_sacker && sp.located) ns.push_back(sp);
    std::sort(ns.begin(), ns.end(), [](const SpecialPoint& a, const SpecialPoint& b) { return a.lambda < b.lambda; });
    return ns;
  }
  TorusOptions options(int max_points = 5000) const {
    TorusOptions o;
    o.omega_min = 1.0;
    o.omega_max = 1.3;
    o.continuation = c.nfrc.continuation;
    o.continuation.max_points = max_points;
    return o;
  }
};

// Largest entry of |analytic - central differences| over the largest analytic entry, for the
// Jacobian in u (omega2 included) and the derivative in omega.
void expect_jacobian_matches_differences(TorusSystem& system, const VectorXd& u, double omega, const char* what) {
  VectorXd r, r_omega;
  MatrixXd j;
  system.evaluate(u, omega, r, &j, &r_omega);
  const VectorXd scale = system.unknown_scale(u);
  MatrixXd differences(j.rows(), j.cols());
  VectorXd plus, minus;
  for (int k = 0; k < system.size(); ++k) {
    const double h = 1e-6 * scale(k);
    VectorXd shifted = u;
    shifted(k) += h;
    system.evaluate(shifted, omega, plus, nullptr, nullptr);
    shifted(k) -= 2 * h;
    system.evaluate(shifted, omega, minus, nullptr, nullptr);
    differences.col(k) = (plus - minus) / (2 * h);
  }
  const double h = 1e-6 * omega;
  system.evaluate(u, omega + h, plus, nullptr, nullptr);
  system.evaluate(u, omega - h, minus, nullptr, nullptr);
  const VectorXd omega_differences = (plus - minus) / (2 * h);
  const double j_error = (j - differences).cwiseAbs().maxCoeff() / j.cwiseAbs().maxCoeff();
  const double omega_error = (r_omega - omega_differences).cwiseAbs().maxCoeff() / r_omega.cwiseAbs().maxCoeff();
  const double omega2_error = (j.col(system.size() - 1) - differences.col(system.size() - 1)).cwiseAbs().maxCoeff() /
                              j.col(system.size() - 1).cwiseAbs().maxCoeff();
  std::printf("%s: Jacobian %.2e, omega2 column %.2e, d/domega %.2e (relative to the largest entry)\n", what, j_error, omega2_error,
              omega_error);
  // Central differences at a step 1e-6 of the unknowns' scale: truncation ~1e-12, round-off
  // ~1e-16 |R| / 1e-6 ~ 1e-10 relative; 1e-7 leaves room and catches any missing term.
  EXPECT_LT(j_error, 1e-7) << what;
  EXPECT_LT(omega2_error, 1e-7) << what;
  EXPECT_LT(omega_error, 1e-7) << what;
}

// A torus state with every coefficient set (deterministic), of size `amplitude`.
VectorXd some_torus(const TorusSystem& system, double amplitude, double omega2) {
  VectorXd u(system.size());
  for (int k = 0; k < system.harmonic_unknowns(); ++k) u(k) = amplitude * std::sin(1.7 * k + 0.3) / (1.0 + 0.2 * (k / system.dofs()));
  u(system.harmonic_unknowns()) = omega2;
  return u;
}

// The absorber with a third, linear dof on the primary (mass 0.02, spring 5, damper 0.002: its
// own frequency 15.8 rad/s, far above the band): the torus condenses it out unless an output reads it.
std::string absorber_with_a_linear_dof(bool output_on_it) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / (output_on_it ? "hbtrack_torus_three_dofs_all.toml" : "hbtrack_torus_three_dofs.toml");
  std::ofstream out(path);
  out << "[model]\ndofs = [\"x1\", \"x2\", \"x3\"]\n"
         "M = [[1.0, 0.0, 0.0], [0.0, 0.05, 0.0], [0.0, 0.0, 0.02]]\n"
         "K = [[6.0454, -0.0454, -5.0], [-0.0454, 0.0454, 0.0], [-5.0, 0.0, 5.0]]\n"
         "[damping]\nC = [[0.0168, -0.0128, -0.002], [-0.0128, 0.0128, 0.0], [-0.002, 0.0, 0.002]]\n"
         "[[forcing]]\ndof = \"x1\"\ncos = 1.0\n[parameters]\namplitude = 0.12\n"
         "[[elements]]\ntype = \"cubic_spring\"\ndofs = [\"x1\"]\ncubic_stiffness = 1.0\n"
         "[[elements]]\ntype = \"cubic_spring\"\ndofs = [\"x2\", \"x1\"]\ncubic_stiffness = 0.0042\n"
         "[harmonic_balance]\nharmonics = 5\nsamples = 64\n"
         "[continuation]\nomega_start = 0.5\nomega_end = 2.5\nstep = 0.01\n"
         "[[outputs]]\nname = \"x1\"\ndof = \"x1\"\n[[outputs]]\nname = \"x2\"\ndof = \"x2\"\n";
  if (output_on_it) out << "[[outputs]]\nname = \"x3\"\ndof = \"x3\"\n";
  return path.string();
}

}  // namespace

TEST(Torus, CondensedResidualJacobianMatchesCentralDifferences) {
  // x3 condensed out pair by pair: the Schur complement's frequency derivative (omega2 column,
  // d/domega) and the forcing it carries.
  const CaseDefinition c = load_case(absorber_with_a_linear_dof(false));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  TorusSystem condensed(hbm, TorusBasis(5, 3, 64, 16), tracking_scales(hbm, c.nfrc, 0.3), torus_retained_dofs(hbm, c.outputs));
  ASSERT_EQ(condensed.dofs(), 2);
  expect_jacobian_matches_differences(condensed, some_torus(condensed, 0.5, 0.1), 1.15, "absorber with x3 condensed out");
}

TEST(Torus, CondensedBranchEqualsTheFullOne) {
  // The same model with x3 an output (kept) and not (condensed out): the NS point, the first
  // torus (its size fixed, omega free) and the envelopes agree to the Newton tolerance.
  std::vector<TorusBranchResult> runs;
  for (const bool keep : {true, false}) {
    const CaseDefinition c = load_case(absorber_with_a_linear_dof(keep));
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    std::vector<SpecialPoint> ns;
    for (const SpecialPoint& sp : compute_nfrc(hbm, c.nfrc, {}).continuation.special_points)
      if (sp.type == SpecialPointType::neimark_sacker && sp.located) ns.push_back(sp);
    ASSERT_FALSE(ns.empty());
    std::sort(ns.begin(), ns.end(), [](const SpecialPoint& a, const SpecialPoint& b) { return a.lambda < b.lambda; });
    TorusOptions o;
    o.omega_min = 1.0, o.omega_max = 1.3, o.continuation = c.nfrc.continuation, o.continuation.max_points = 1;
    runs.push_back(torus_branch(hbm, ns[0].u, ns[0].lambda, tracking_scales(hbm, c.nfrc, 0.3), o, c.outputs));
    ASSERT_EQ(runs.back().points.size(), 2u);
  }
  const TorusPoint &full = runs[0].points[1], &condensed = runs[1].points[1];
  std::printf("first torus: omega %.10f / %.10f, omega2 %.10f / %.10f, max x2 %.8f / %.8f\n", full.omega, condensed.omega, full.omega2,
              condensed.omega2, full.envelope[1].max, condensed.envelope[1].max);
  EXPECT_EQ(runs[0].phase_dof, runs[1].phase_dof);
  // Both Newton solves stop at a residual of 1e-8 of the force (the case's tolerance): the
  // unknowns agree to about that times the system's condition, far below the torus' own
  // omega - omega_NS (1e-4): 1e-7.
  EXPECT_NEAR(full.omega, condensed.omega, 1e-7);
  EXPECT_NEAR(full.omega2, condensed.omega2, 1e-7);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(full.envelope[static_cast<size_t>(k)].max, condensed.envelope[static_cast<size_t>(k)].max, 1e-7);
    EXPECT_NEAR(full.envelope[static_cast<size_t>(k)].min, condensed.envelope[static_cast<size_t>(k)].min, 1e-7);
  }
}

TEST(Torus, ResidualJacobianMatchesCentralDifferences) {
  Absorber a;
  TorusSystem absorber(a.hbm, TorusBasis(5, 3, 64, 16), a.scales);
  expect_jacobian_matches_differences(absorber, some_torus(absorber, 0.5, 0.1), 1.15, "absorber (cubic springs)");
  // Velocity-dependent law (regularised Coulomb friction) with a forcing growing with omega:
  // the velocity's omega and omega2 terms and the forcing's derivative.
  const CaseDefinition f =
      load_case(test::source_path("examples/friction_damper.toml"), {"forcing_growth.exponent=2", "forcing_growth.reference_frequency=1"});
  HarmonicBalance friction(f.model, f.elements, f.parameters, f.harmonic_balance);
  TorusSystem damper(friction, TorusBasis(3, 2, 16, 8), tracking_scales(friction, f.nfrc, 1.0));
  const double omega = 0.5 * (f.nfrc.omega_start + f.nfrc.omega_end);
  expect_jacobian_matches_differences(damper, some_torus(damper, 0.01, 0.05 * omega), omega, "friction damper (tanh friction)");
}

TEST(Torus, RefusesALawWithMemoryNamingTheElement) {
  // A hysteresis finds its steady state over a period; a torus has none.
  const CaseDefinition c = load_case(test::source_path("examples/iwan_joint.toml"));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  try {
    TorusSystem system(hbm, TorusBasis(3, 2, 16, 8), tracking_scales(hbm, c.nfrc, 1.0));
    FAIL() << "an Iwan joint was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("torus: elements[0] (iwan): its force depends on its past"), std::string::npos) << e.what();
  }
}

TEST(Torus, BranchIsBornAtOneNsPointAndClosesAtTheOther) {
  Absorber a;
  const std::vector<SpecialPoint> ns = a.ns_points();
  ASSERT_EQ(ns.size(), 2u);
  TorusOptions options = a.options();
  if (test::kSanitizedBuild) {
    // 5 minutes there at the default H2 = 4, N2 = 32; H2 = 2, N2 = 8 is 13 times cheaper and
    // ends as close to NS 2 (1.3e-5 in omega). The Release pass runs the default.
    options.h2 = 2;
    options.n2 = 8;
  }
  const TorusBranchResult r = torus_branch(a.hbm, ns[0].u, ns[0].lambda, a.scales, options, a.c.outputs);
  ASSERT_GT(r.points.size(), 10u);
  std::printf("NS 1: omega %.8f (NFRC's located %.8f), nu %.8f, phase pair (%d,%d) of dof %d; %zu points, %s\n", r.omega_ns, ns[0].lambda,
              r.nu, r.k1, r.k2, r.phase_dof, r.points.size(), to_string(r.stop_reason).c_str());
  // Row 0 is the NS point: the periodic solution, a torus of size 0, omega2 = the NS frequency.
  EXPECT_EQ(r.points[0].omega, r.omega_ns);
  EXPECT_EQ(r.points[0].omega2, r.nu);
  EXPECT_NEAR(r.omega_ns, ns[0].lambda, 1e-6);  // the NFRC locates its test function's zero to about that
  // The branch ends where the torus shrinks back onto the periodic branch: NS 2, with its NS frequency.
  EXPECT_EQ(r.stop_reason, StopReason::reached_ns_point);
  const TorusBranchResult other = torus_branch(a.hbm, ns[1].u, ns[1].lambda, a.scales, a.options(1), a.c.outputs);
  const TorusPoint& last = r.points.back();
  double largest = 0;
  for (const TorusPoint& p : r.points) largest = std::max(largest, p.size);
  std::printf("last torus: omega %.8f omega2 %.8f size %.4f (of %.4f); NS 2: omega %.8f nu %.8f\n", last.omega, last.omega2, last.size,
              largest, other.omega_ns, other.nu);
  // Its size there is a few % of the largest; omega and omega2 move with the size squared near
  // an NS point (1e-4 and 1e-3 at 10 %, from the start below): closer than that.
  EXPECT_LT(last.size, 0.1 * largest);
  EXPECT_NEAR(last.omega, other.omega_ns, 1e-4);
  EXPECT_NEAR(last.omega2, other.nu, 1e-3);
  // The torus from NS 2 lies below it in omega (inside the band) too.
  ASSERT_EQ(other.points.size(), 2u);
  EXPECT_LT(other.points[1].omega, other.omega_ns);
}

TEST(Torus, FirstToriTendToTheNsPointAsTheirSizeVanishes) {
  Absorber a;
  const std::vector<SpecialPoint> ns = a.ns_points();
  ASSERT_EQ(ns.size(), 2u);
  // The first torus at sizes eps = 4, 2, 1 % of the periodic amplitude: omega - omega_NS and
  // omega2 - nu go as eps^2 (the NS normal form), the envelope - the periodic extremes as eps.
  std::vector<double> d_omega, d_omega2, d_envelope;
  for (double fraction : {0.04, 0.02, 0.01}) {
    TorusOptions o = a.options(1);
    o.start_fraction = fraction;
    const TorusBranchResult r = torus_branch(a.hbm, ns[0].u, ns[0].lambda, a.scales, o, a.c.outputs);
    ASSERT_EQ(r.points.size(), 2u);
    const TorusPoint &ns_row = r.points[0], &first = r.points[1];
    d_omega.push_back(first.omega - ns_row.omega);
    d_omega2.push_back(first.omega2 - ns_row.omega2);
    d_envelope.push_back(first.envelope[1].max - ns_row.envelope[1].max);  // x2, the absorber
    std::printf("eps %.2f: omega - omega_NS %.3e, omega2 - nu %.3e, max x2 - periodic %.3e\n", fraction, d_omega.back(), d_omega2.back(),
                d_envelope.back());
  }
  for (size_t i = 0; i + 1 < d_omega.size(); ++i) {
    EXPECT_NEAR(d_omega[i] / d_omega[i + 1], 4.0, 0.4);  // quadratic, up to the eps^4 term
    EXPECT_NEAR(d_omega2[i] / d_omega2[i + 1], 4.0, 0.4);
    EXPECT_NEAR(d_envelope[i] / d_envelope[i + 1], 2.0, 0.2);  // linear, up to the eps^2 term
  }
  EXPECT_GT(d_omega.back(), 0.0);  // supercritical: the torus lies in the unstable band, above NS 1
}

}  // namespace hbtrack_tests::file_torus
