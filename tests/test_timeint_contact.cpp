// Time integration of the two-dof example with a penalty unilateral spring (C0 force) against
// its harmonic balance solution on the stable contact branch.
#include <gtest/gtest.h>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/timeint/dormand_prince_integrator.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_timeint_contact {

using namespace hbtrack;

namespace {

// A point of the upper, in-contact branch inside the fold (three solutions coexist there,
// 0.689 < omega < 0.770): the HBM point the test starts from, with its recorded outputs.
struct ContactPoint {
  CaseDefinition c;
  double omega = 0;
  MotionState start;
  RecordedPoint hbm;
};

ContactPoint compute_upper_branch_point(double target_omega) {
  ContactPoint p;
  p.c = load_case(test::source_path("examples/two_dof_contact.toml"));
  HarmonicBalance hbm(p.c.model, p.c.elements, p.c.parameters, p.c.harmonic_balance);
  NfrcOptions range = p.c.nfrc;
  range.omega_end = 0.8;  // the fold is all we need
  // The engine locates the fold by itself; the Floquet analysis (shooting at every point of this
  // C0 law) would be most of the cost, minutes under the sanitizers, and nothing here reads it.
  range.stability.method = StabilityMethod::none;
  const NfrcResult nfrc = compute_nfrc(hbm, range, p.c.outputs);
  // Without stability the engine's LP/BP test alone marks points: the fold is the first LP.
  int first_fold = -1;
  for (const SpecialPoint& sp : nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point && first_fold < 0) first_fold = sp.index;
  EXPECT_GT(first_fold, 0);
  // The upper branch ends at the first limit point; take its point nearest to the target.
  int best = 0;
  for (int i = 0; i < first_fold; ++i)
    if (std::abs(nfrc.recorded[static_cast<size_t>(i)].omega - target_omega) <
        std::abs(nfrc.recorded[static_cast<size_t>(best)].omega - target_omega))
      best = i;
  const BranchPoint& b = nfrc.continuation.points[static_cast<size_t>(best)];
  p.omega = b.lambda;
  p.hbm = nfrc.recorded[static_cast<size_t>(best)];
  p.start = state_from_harmonics(hbm.expand(b.u, p.omega), p.c.model.dofs(), p.c.harmonic_balance.harmonics, p.omega);
  return p;
}

// Computed once for the tests of this file (the NFRC is the expensive part).
const ContactPoint& upper_branch_point() {
  static const ContactPoint point = compute_upper_branch_point(0.72);
  return point;
}

void expect_extremes_match(const ContactPoint& p, const SteadyStateResult& r, double tolerance, const char* method) {
  ASSERT_TRUE(r.converged) << r.stop_reason;
  ASSERT_EQ(r.outputs.size(), p.hbm.outputs.size());
  double worst = 0;
  for (size_t i = 0; i < r.outputs.size(); ++i) {
    const OutputValues& expected = p.hbm.outputs[i];
    // Relative to the output's peak-to-peak: min and max are on the same footing.
    const double range = expected.max - expected.min;
    EXPECT_NEAR(r.outputs[i].max, expected.max, tolerance * range) << p.c.outputs[i].name;
    EXPECT_NEAR(r.outputs[i].min, expected.min, tolerance * range) << p.c.outputs[i].name;
    worst = std::max({worst, std::abs(r.outputs[i].max - expected.max) / range, std::abs(r.outputs[i].min - expected.min) / range});
  }
  // The motion is in contact: x2 goes beyond the clearance.
  EXPECT_GT(r.outputs[1].max, p.c.parameters.value("clearance"));
  std::printf("[ measured ] %s at omega %.4f: %d periods, %ld steps, %ld force evaluations, worst extreme %.2e of range\n", method, p.omega,
              r.periods, r.statistics.steps, r.statistics.force_evaluations, worst);
}

}  // namespace

TEST(TimeIntegrationContact, NewmarkMatchesTheHbmExtremesOnTheStableContactBranch) {
  const ContactPoint& p = upper_branch_point();
  ASSERT_GT(p.omega, 0.70);
  ASSERT_LT(p.omega, 0.74);
  EquationOfMotion eom(p.c.model, p.c.elements, p.c.parameters, p.omega);
  NewmarkIntegrator integrator(eom, NewmarkOptions{});
  const SteadyStateResult r = integrate_to_steady_state(integrator, p.start, p.c.outputs, SteadyStateOptions{});
  expect_extremes_match(p, r, 0.01, "newmark");
}

TEST(TimeIntegrationContact, DormandPrinceAgreesOnTheSoftContact) {
  // The contact stiffness (5) is soft: the explicit method's step is set by accuracy.
  const ContactPoint& p = upper_branch_point();
  EquationOfMotion eom(p.c.model, p.c.elements, p.c.parameters, p.omega);
  DormandPrinceIntegrator integrator(eom, DormandPrinceOptions{});
  const SteadyStateResult r = integrate_to_steady_state(integrator, p.start, p.c.outputs, SteadyStateOptions{});
  expect_extremes_match(p, r, 0.01, "dopri5");
}

namespace {

// The example with a penalty stiffness 10^4 times larger (contact frequency 224 rad/s, 345
// times the forcing), forced at 0.65 where a single solution exists.
struct StiffContact {
  CaseDefinition c = load_case(test::source_path("examples/two_dof_contact.toml"));
  double omega = 0.65;
  StiffContact() { c.elements.at(0)->properties.at(0) = ParameterBinding::constant(50000.0); }
};

SteadyStateResult simulate(const StiffContact& s, TimeIntegrator& integrator, int max_periods = 2000) {
  SteadyStateOptions options;
  options.harmonics = s.c.harmonic_balance.harmonics;
  options.max_periods = max_periods;
  return integrate_to_steady_state(integrator, rest_state(2), s.c.outputs, options);
}

// The largest difference of an output's max or min from the reference's, over its peak-to-peak.
double worst_extreme(const SteadyStateResult& r, const SteadyStateResult& reference) {
  double worst = 0;
  for (size_t i = 0; i < r.outputs.size(); ++i) {
    const double range = reference.outputs[i].max - reference.outputs[i].min;
    worst = std::max({worst, std::abs(r.outputs[i].max - reference.outputs[i].max) / range,
                      std::abs(r.outputs[i].min - reference.outputs[i].min) / range});
  }
  return worst;
}

}  // namespace

TEST(TimeIntegrationContact, StiffPenaltyContactNeedsTheRefinedSteps) {
  const StiffContact s;
  EquationOfMotion eom(s.c.model, s.c.elements, s.c.parameters, s.omega);
  NewmarkIntegrator newmark(eom, NewmarkOptions{});
  DormandPrinceIntegrator dopri5(eom, DormandPrinceOptions{});
  const SteadyStateResult implicit = simulate(s, newmark), reference = simulate(s, dopri5);
  ASSERT_TRUE(implicit.converged) << implicit.stop_reason;
  ASSERT_TRUE(reference.converged) << reference.stop_reason;
  const double worst = worst_extreme(implicit, reference);
  EXPECT_LT(worst, 0.005);
  // The refinement only acts around the contacts: well under twice the base steps.
  EXPECT_LT(implicit.statistics.steps, 2 * 256 * implicit.periods);
  std::printf(
      "[ measured ] k = 5e4: newmark %d periods %ld steps %ld force evaluations; dopri5 %d periods %ld steps %ld force "
      "evaluations; worst extreme %.2e of range\n",
      implicit.periods, implicit.statistics.steps, implicit.statistics.force_evaluations, reference.periods, reference.statistics.steps,
      reference.statistics.force_evaluations, worst);

  // The same fixed-step scheme without the refinement does not settle (energy errors at the
  // impacts keep the motion from repeating).
  NewmarkOptions fixed;
  fixed.max_refinements = 0;
  NewmarkIntegrator fixed_step(eom, fixed);
  const SteadyStateResult unrefined = simulate(s, fixed_step, 400);
  EXPECT_FALSE(unrefined.converged);
  std::printf("[ measured ] k = 5e4, fixed step: %s after %d periods, last change %.2e\n", to_string(unrefined.stop_reason).c_str(),
              unrefined.periods, unrefined.last_change);
}

TEST(TimeIntegrationContact, ContactResolvedWithFewerStepsNeedNotSettleOnAStiffImpact) {
  // element_steps = 32: a step is halved only until the contact's own period (224 rad/s here)
  // has 32 steps instead of the forcing's 256. On rotor 67's smooth contact that settles as the
  // default does (docs/time-integration.md); on this C0 penalty impact, 345 times the forcing,
  // the energy errors at the impacts come back as in the fixed-step run above: the motion does
  // not repeat within 2000 periods, though its extremes stay within the default's 0.5 % of the
  // range against dopri5. So the option is a per-case choice and the default stays N.
  const StiffContact s;
  EquationOfMotion eom(s.c.model, s.c.elements, s.c.parameters, s.omega);
  NewmarkIntegrator fine(eom, NewmarkOptions{});
  NewmarkOptions coarse_options;
  coarse_options.element_steps = 32;
  NewmarkIntegrator coarse(eom, coarse_options);
  DormandPrinceIntegrator dopri5(eom, DormandPrinceOptions{});
  const SteadyStateResult resolved = simulate(s, fine), fewer = simulate(s, coarse), reference = simulate(s, dopri5);
  ASSERT_TRUE(resolved.converged) << resolved.stop_reason;
  ASSERT_TRUE(reference.converged) << reference.stop_reason;
  EXPECT_FALSE(fewer.converged);
  const double worst = worst_extreme(fewer, reference);
  EXPECT_LT(worst, 0.005);
  const double steps_per_period = static_cast<double>(fewer.statistics.steps) / fewer.periods;
  const double resolved_steps_per_period = static_cast<double>(resolved.statistics.steps) / resolved.periods;
  EXPECT_LT(steps_per_period, resolved_steps_per_period);
  EXPECT_GE(steps_per_period, 256.0) << "the base step is never lengthened";
  std::printf(
      "[ measured ] k = 5e4, element_steps 32: %s after %d periods (last change %.1e), %.0f steps a period (default %.0f), "
      "worst extreme %.2e of range\n",
      to_string(fewer.stop_reason).c_str(), fewer.periods, fewer.last_change, steps_per_period, resolved_steps_per_period, worst);
  NewmarkOptions refused;
  refused.element_steps = -1;
  EXPECT_THROW(refused.validate(), std::invalid_argument);
}

}  // namespace hbtrack_tests::file_timeint_contact
