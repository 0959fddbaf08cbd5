// The harmonic balance system is constant during every analysis: limit-point tracking and a
// continuation in a parameter evaluate their own copies, so the caller's evaluator answers the
// same, bit for bit, before, during and after them; and evaluators on one shared system, each
// with its own workspace, give in parallel threads what they give one after the other.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/analysis/parameter_continuation.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_constant_system {

using namespace hbtrack;

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Everything an evaluator answers at (x, omega) that depends on its parameter values.
struct Answers {
  VectorXd r, r_omega, r_parameter, full;
  MatrixXd jacobian;
  bool operator==(const Answers& o) const {
    return r == o.r && r_omega == o.r_omega && r_parameter == o.r_parameter && full == o.full && jacobian == o.jacobian;
  }
};

Answers answers(HarmonicBalance& hbm, const VectorXd& x, double omega, int parameter) {
  Answers a;
  hbm.evaluate(x, omega, a.r, &a.jacobian, &a.r_omega);
  a.r_parameter = hbm.parameter_derivative(x, omega, parameter);
  a.full = hbm.expand(x, omega);
  return a;
}

// The caller's evaluator as it stands, through a copy (the caller holds it const).
Answers answers_of(const HarmonicBalance& caller, const VectorXd& x, double omega, int parameter) {
  HarmonicBalance copy(caller);
  return answers(copy, x, omega, parameter);
}

TEST(ConstantSystem, FoldTrackingLeavesTheCallersEvaluatorUntouched) {
  const CaseDefinition c = load_case(test::source_path("examples/duffing.toml"), {});
  const HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const int amplitude = hbm.amplitude_parameter();
  HarmonicBalance finder(hbm);
  NfrcOptions nfrc = c.nfrc;
  nfrc.stability.method = StabilityMethod::none;
  const NfrcResult frc = compute_nfrc(finder, nfrc, {});
  const SpecialPoint* lp = nullptr;
  for (const SpecialPoint& sp : frc.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point && sp.located && !lp) lp = &sp;
  ASSERT_NE(lp, nullptr) << "the Duffing NFRC has limit points";

  const ParameterValues values = hbm.parameter_values();
  const Answers before = answers_of(hbm, lp->u, lp->lambda, amplitude);
  FoldTrackingOptions o;
  o.parameter_min = 0.8;
  o.parameter_max = 1.3;
  o.continuation = c.nfrc.continuation;
  const double reference = automatic_length_scale(finder, c.nfrc.omega_start, c.nfrc.omega_end);
  const FoldScales scales{0.01 * reference, c.nfrc.omega_end - c.nfrc.omega_start, force_scale(finder, reference), 0.5};
  int moved = 0, unchanged = 0;
  const FoldTrackingResult r = track_fold(hbm, amplitude, lp->u, lp->lambda, scales, o, {}, [&](const FoldCurvePoint& p, int) {
    // While the curve is at another amplitude, the caller's evaluator is still at its own.
    if (p.parameter != values[static_cast<size_t>(amplitude)]) ++moved;
    if (hbm.parameter_values() == values && answers_of(hbm, lp->u, lp->lambda, amplitude) == before) ++unchanged;
    return true;
  });
  ASSERT_TRUE(r.success()) << r.legs.back().stop_reason;
  EXPECT_GT(moved, 2) << "the curve must leave the start's amplitude for the check to mean something";
  EXPECT_EQ(unchanged, static_cast<int>(r.points.size()));
  EXPECT_TRUE(hbm.parameter_values() == values);
  EXPECT_TRUE(answers_of(hbm, lp->u, lp->lambda, amplitude) == before);
}

TEST(ConstantSystem, ParameterContinuationLeavesTheCallersEvaluatorUntouched) {
  const CaseDefinition c = load_case(test::source_path("examples/chain_contact.toml"), {});
  const HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const int clearance = hbm.parameters().find("clearance");
  const double omega = c.nfrc.omega_start;
  HarmonicBalance probe(hbm);
  const VectorXd x = probe.linear_solution(omega);
  const Answers before = answers_of(hbm, x, omega, clearance);
  int points = 0, unchanged = 0;
  NfrcOptions options = c.nfrc;
  options.stability.method = StabilityMethod::none;
  options.continuation.max_points = 8;
  continue_in_parameter(hbm, hbm.amplitude_parameter(), omega, 0.5, 2.0, options, c.outputs,
                        [&](const BranchPoint&, const ParameterBranchPoint&, int) {
                          ++points;
                          if (answers_of(hbm, x, omega, clearance) == before) ++unchanged;
                          return true;
                        });
  EXPECT_GT(points, 2);
  EXPECT_EQ(unchanged, points);
  EXPECT_TRUE(answers_of(hbm, x, omega, clearance) == before);
}

TEST(ConstantSystem, ThreadsWithTheirOwnWorkspacesMatchSequentialEvaluation) {
  const CaseDefinition c = load_case(test::source_path("examples/chain_contact.toml"), {});
  const auto system = std::make_shared<const HarmonicBalanceSystem>(c.model, c.elements, c.parameters, c.harmonic_balance);
  ASSERT_LT(system->retained_dofs(), system->model().dofs()) << "the recovery of condensed dofs must be part of the check";
  const int clearance = system->parameters().find("clearance");
  ParameterValues other = system->parameters().values();
  other[static_cast<size_t>(system->amplitude_parameter())] = 0.7;
  other[static_cast<size_t>(clearance)] = 0.03;
  // A state in contact: the linear solution scaled up, at omegas across the case's range.
  const int count = 24;
  std::vector<double> omegas;
  std::vector<VectorXd> states;
  HarmonicBalance probe(system);
  for (int i = 0; i < count; ++i) {
    omegas.push_back(c.nfrc.omega_start + (c.nfrc.omega_end - c.nfrc.omega_start) * i / (count - 1));
    states.push_back(4.0 * probe.linear_solution(omegas.back()));
  }
  // Through the evaluator (nominal values) and through the system itself (other values).
  auto nominal_run = [&](std::vector<Answers>& out) {
    HarmonicBalance hbm(system);
    for (int i = 0; i < count; ++i) out.push_back(answers(hbm, states[static_cast<size_t>(i)], omegas[static_cast<size_t>(i)], clearance));
  };
  auto other_run = [&](std::vector<Answers>& out) {
    HarmonicBalanceWorkspace ws(*system);
    for (int i = 0; i < count; ++i) {
      const VectorXd& x = states[static_cast<size_t>(i)];
      const double omega = omegas[static_cast<size_t>(i)];
      Answers a;
      system->evaluate(other, ws, x, omega, a.r, &a.jacobian, &a.r_omega);
      a.r_parameter = system->parameter_derivative(other, ws, x, omega, clearance);
      a.full = system->expand(other, ws, x, omega);
      out.push_back(a);
    }
  };
  std::vector<Answers> nominal_sequential, other_sequential, nominal_parallel, other_parallel;
  nominal_run(nominal_sequential);
  other_run(other_sequential);
  std::thread first([&] { nominal_run(nominal_parallel); });
  std::thread second([&] { other_run(other_parallel); });
  first.join();
  second.join();
  ASSERT_EQ(nominal_parallel.size(), nominal_sequential.size());
  ASSERT_EQ(other_parallel.size(), other_sequential.size());
  int differ = 0;
  for (int i = 0; i < count; ++i) {
    const size_t k = static_cast<size_t>(i);
    EXPECT_TRUE(nominal_parallel[k] == nominal_sequential[k]) << "omega " << omegas[k];
    EXPECT_TRUE(other_parallel[k] == other_sequential[k]) << "omega " << omegas[k];
    differ += !(nominal_sequential[k].r == other_sequential[k].r);
  }
  EXPECT_EQ(differ, count) << "the two parameter sets must give different residuals for the check to mean something";
}

TEST(ConstantSystem, AWorkspaceOfAnotherSystemOrWrongValuesAreRefused) {
  const CaseDefinition c = load_case(test::source_path("examples/duffing.toml"), {});
  const HarmonicBalanceSystem one(c.model, c.elements, c.parameters, c.harmonic_balance);
  const HarmonicBalanceSystem two(c.model, c.elements, c.parameters, c.harmonic_balance);
  HarmonicBalanceWorkspace of_two(two);
  const VectorXd x = VectorXd::Zero(one.unknowns());
  VectorXd r;
  EXPECT_THROW(one.evaluate(one.parameters().values(), of_two, x, 1.0, r), std::logic_error);
  HarmonicBalanceWorkspace of_one(one);
  EXPECT_THROW(one.evaluate(ParameterValues{}, of_one, x, 1.0, r), std::logic_error);
  EXPECT_NO_THROW(one.evaluate(one.parameters().values(), of_one, x, 1.0, r));
}

}  // namespace

}  // namespace hbtrack_tests::file_constant_system
