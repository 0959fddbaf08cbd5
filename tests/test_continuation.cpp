// The continuation engine on problems with known answers, independent of harmonic balance, and
// every predictor/corrector combination on the Duffing example.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_continuation {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// R(u, lambda) = u^3 - u + lambda, a cubic fold: lambda = u - u^3 has limit points
// at u = +-1/sqrt(3), lambda = +-2/(3 sqrt(3)).
class CubicFold final : public ContinuationProblem {
 public:
  int size() const override { return 1; }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jac, VectorXd* r_lambda) override {
    r.resize(1);
    r(0) = u(0) * u(0) * u(0) - u(0) + lambda;
    if (jac) {
      jac->resize(1, 1);
      (*jac)(0, 0) = 3 * u(0) * u(0) - 1;
      r_lambda->resize(1);
      (*r_lambda)(0) = 1.0;
    }
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(1); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }
};

// m cubic folds weakly coupled by a fixed symmetric matrix: R = u.^3 - u + B u + lambda,
// |B_ij| <= 0.01. Its branch has limit points, and its tangents need m x m bordered solves.
class CoupledCubics final : public ContinuationProblem {
 public:
  explicit CoupledCubics(int m) {
    std::srand(11);
    const MatrixXd random = MatrixXd::Random(m, m);
    coupling_ = 0.005 * (random + random.transpose());
  }
  int size() const override { return static_cast<int>(coupling_.rows()); }
  void evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jac, VectorXd* r_lambda) override {
    r = (u.array().cube() - u.array() + lambda).matrix() + coupling_ * u;
    if (jac) {
      *jac = coupling_;
      jac->diagonal().array() += 3 * u.array().square() - 1;
      r_lambda->setOnes(size());
    }
  }
  VectorXd unknown_scale(const VectorXd&) const override { return VectorXd::Ones(size()); }
  double parameter_scale() const override { return 1.0; }
  double residual_scale() const override { return 1.0; }

 private:
  MatrixXd coupling_;
};

}  // namespace

TEST(Continuation, TangentsRefinedFromNewtonFactorsAgreeWithFreshOnes) {
  CoupledCubics problem(12);
  ContinuationOptions o;
  o.step_max = 0.05;
  // Plain Newton: the tangent then starts from the factors of the corrector's last iteration.
  o.reuse_factorization = false;
  const ContinuationResult r = continue_branch(problem, VectorXd::Constant(12, -1.3), 1.0, -1.0, o);
  // The weak coupling splits the m simultaneous folds: the branch turns at the first and
  // wanders through the 2^m solutions' folds. Which way it goes at each near-simultaneous pair
  // depends on the step sequence: with the steps capped at 0.05 it returned to lambda = 1
  // ("left_range") after 3040 points; with steps sized by the turn it is still wandering at
  // max_points. Either way it is a branch through limit points, which is what this test needs.
  ASSERT_TRUE(r.summary.stop_reason == StopReason::left_range || r.summary.stop_reason == StopReason::reached_end ||
              r.summary.stop_reason == StopReason::max_points)
      << r.summary.stop_reason;
  ASSERT_GE(r.special_points.size(), 1u);
  ASSERT_GE(r.points.size(), 20u);
  // Most tangents came from the last Newton step's factors: a fresh LU for every tangent would
  // make factorizations >= (Newton steps of the corrector) + points.
  EXPECT_LT(r.summary.factorizations, r.summary.newton_iterations + static_cast<int>(r.points.size()) / 2);
  // Each stored tangent against a fresh LU of [J R_lambda; t^T] t' = e at its point (all scales
  // 1). The refinement stops at a backward error of 1e-13 and these bordered matrices are well
  // conditioned away from the limit points' neighbourhood (cond < 1e3): 1e-9 is roundoff.
  const int m = problem.size();
  VectorXd res, r_lambda;
  MatrixXd jac;
  for (size_t i = 0; i + 1 < r.points.size(); ++i) {  // the last point landed on the bound: its tangent is the step's
    const BranchPoint& p = r.points[i];
    problem.evaluate(p.u, p.lambda, res, &jac, &r_lambda);
    MatrixXd a(m + 1, m + 1);
    a << jac, r_lambda, p.tangent.transpose();
    VectorXd e = VectorXd::Zero(m + 1);
    e(m) = 1.0;
    const VectorXd fresh = a.partialPivLu().solve(e).normalized();
    EXPECT_LE((fresh - p.tangent).norm(), 1e-9) << "point " << i;
  }
}

TEST(Continuation, FollowsAFoldAndFlagsBothLimitPoints) {
  for (const char* predictor : {"tangent", "secant"}) {
    for (const char* corrector : {"pseudo_arclength", "hypersphere"}) {
      CubicFold problem;
      ContinuationOptions o;
      o.predictor = parse_predictor(predictor);
      o.corrector = parse_corrector(corrector);
      o.step = 0.02;
      o.step_max = 0.05;
      // Start on the lower branch at lambda = 1 (u ~ -1.32), go towards lambda = -1.
      const ContinuationResult r = continue_branch(problem, VectorXd::Constant(1, -1.3), 1.0, -1.0, o);
      ASSERT_EQ(r.summary.stop_reason, StopReason::reached_end) << predictor << "/" << corrector;
      // Every point is on the curve.
      for (const BranchPoint& p : r.points) EXPECT_NEAR(p.u(0) * p.u(0) * p.u(0) - p.u(0) + p.lambda, 0.0, 1e-9);
      EXPECT_DOUBLE_EQ(r.points.back().lambda, -1.0);
      ASSERT_EQ(r.special_points.size(), 2u) << predictor << "/" << corrector;
      // Flagged at a branch point next to the fold: within one step (0.05) of the exact value.
      const double lp = 2.0 / (3.0 * std::sqrt(3.0));
      EXPECT_NEAR(r.special_points[0].lambda, -lp, 0.05);
      EXPECT_NEAR(r.special_points[1].lambda, lp, 0.05);
    }
  }
}

TEST(Continuation, StartedOnAFoldItLeavesTowardsTheLargerStateWhateverTheWindowsDirection) {
  // On the fold the tangent is (+-1, 0): its lambda sign is rounding, and with it which branch a
  // window's direction picked (the tutorial's isola ran either way round on two BLAS kernels).
  CubicFold problem;
  ContinuationOptions o;
  o.step = 0.02;
  o.max_points = 3;
  const double u_fold = 1 / std::sqrt(3.0), lp = 2.0 / (3.0 * std::sqrt(3.0));
  for (int direction : {1, -1}) {
    const ContinuationResult r =
        continue_within(problem, VectorXd::Constant(1, u_fold), lp, ParameterWindow{-1.0, 1.0, direction, false}, o);
    ASSERT_GE(r.points.size(), 2u) << direction;
    EXPECT_GT(r.points[1].u(0), u_fold) << direction;  // |u| grows: onto the branch u > 1/sqrt(3)
    EXPECT_LT(r.points[1].lambda, lp) << direction;
  }
  // Off the fold the window's direction decides, as before: from u = 0.9 (lambda 0.171) with
  // lambda decreasing the branch goes to larger u, with lambda increasing towards the fold.
  const ContinuationResult up = continue_within(problem, VectorXd::Constant(1, 0.9), 0.9 - 0.729, ParameterWindow{-1.0, 1.0, 1, false}, o);
  ASSERT_GE(up.points.size(), 2u);
  EXPECT_LT(up.points[1].u(0), 0.9);
}

TEST(Continuation, ObserverCanInterrupt) {
  CubicFold problem;
  ContinuationOptions o;
  const ContinuationResult r =
      continue_branch(problem, VectorXd::Constant(1, -1.3), 1.0, -1.0, o, [](const BranchPoint&, int index) { return index < 4; });
  EXPECT_EQ(r.summary.stop_reason, StopReason::interrupted);
  EXPECT_EQ(r.points.size(), 5u);
}

TEST(Continuation, ResumingFromASavedStateRepeatsTheRunExactly) {
  // Secant predictor: the resumed run also needs the point before the last one.
  CubicFold problem;
  ContinuationOptions o;
  o.predictor = Predictor::secant;
  o.step_max = 0.05;
  const ParameterWindow window{-1.0, 1.0, -1, false};
  std::vector<ContinuationState> states;
  ContinuationRestart saving;
  saving.on_state = [&](const ContinuationState& s) { states.push_back(s); };
  saving.state_interval_s = 0;  // a state between every two steps
  const ContinuationResult whole = continue_within(problem, VectorXd::Constant(1, -1.3), 1.0, window, o, {}, nullptr, saving);
  ASSERT_EQ(whole.summary.stop_reason, StopReason::reached_end);
  ASSERT_EQ(whole.special_points.size(), 2u);
  // A state taken before both limit points: the resumed run must find them as the whole run did.
  const int k = 5;
  ASSERT_LT(k, whole.special_points[0].index);
  ASSERT_EQ(states[static_cast<size_t>(k - 1)].points, k);
  ContinuationRestart resuming;
  resuming.resume_from = &states[static_cast<size_t>(k - 1)];
  std::vector<int> indices;
  const ContinuationResult rest = continue_within(
      problem, VectorXd::Zero(1), 1.0, window, o,
      [&](const BranchPoint&, int index) {
        indices.push_back(index);
        return true;
      },
      nullptr, resuming);
  ASSERT_EQ(rest.points.size() + static_cast<size_t>(k), whole.points.size());
  EXPECT_EQ(indices.front(), k);
  // Exact equality: the state holds every double the next step reads.
  for (size_t i = 0; i < rest.points.size(); ++i) {
    EXPECT_EQ(rest.points[i].lambda, whole.points[i + static_cast<size_t>(k)].lambda) << i;
    EXPECT_EQ(rest.points[i].u(0), whole.points[i + static_cast<size_t>(k)].u(0)) << i;
  }
  ASSERT_EQ(rest.special_points.size(), whole.special_points.size());
  for (size_t i = 0; i < rest.special_points.size(); ++i) {
    EXPECT_EQ(rest.special_points[i].lambda, whole.special_points[i].lambda);
    EXPECT_EQ(rest.special_points[i].index, whole.special_points[i].index);
  }
  EXPECT_EQ(rest.summary.points, whole.summary.points);
  EXPECT_EQ(rest.summary.newton_iterations, whole.summary.newton_iterations);
  EXPECT_EQ(rest.summary.jacobian_evaluations, whole.summary.jacobian_evaluations);
}

// The state is saved after the first point, at most every state_interval_s after that, and
// once more at the stop, so that the last one saved covers every accepted point, interrupted or not.
TEST(Continuation, StatesAreSavedAtTheStartAtMostEveryIntervalAndAtTheStop) {
  CubicFold problem;
  ContinuationOptions o;
  o.step_max = 0.05;
  const ParameterWindow window{-1.0, 1.0, -1, false};
  std::vector<int> saved_points;
  ContinuationRestart saving;
  saving.on_state = [&](const ContinuationState& s) { saved_points.push_back(s.points); };
  saving.state_interval_s = 1e9;  // longer than the run: only the first and the last
  const ContinuationResult whole = continue_within(problem, VectorXd::Constant(1, -1.3), 1.0, window, o, {}, nullptr, saving);
  ASSERT_EQ(whole.summary.stop_reason, StopReason::reached_end);
  ASSERT_GT(whole.summary.points, 10);
  EXPECT_EQ(saved_points, (std::vector<int>{1, whole.summary.points}));
  saved_points.clear();
  const ContinuationResult stopped = continue_within(
      problem, VectorXd::Constant(1, -1.3), 1.0, window, o, [](const BranchPoint&, int index) { return index < 6; }, nullptr, saving);
  ASSERT_EQ(stopped.summary.stop_reason, StopReason::interrupted);
  EXPECT_EQ(saved_points, (std::vector<int>{1, 7}));  // the interrupting point is accepted, and saved
}

TEST(Continuation, FailsCleanlyWhenNewtonCannotStart) {
  CubicFold problem;
  ContinuationOptions o;
  o.max_iterations = 1;
  o.tolerance = 1e-300;  // unreachable in floating point
  const ContinuationResult r = continue_branch(problem, VectorXd::Constant(1, 5.0), 1.0, -1.0, o);
  EXPECT_EQ(r.summary.stop_reason, StopReason::no_convergence_at_start);
  EXPECT_FALSE(r.success());
}

TEST(Continuation, OptionsAreValidatedWithTheFieldName) {
  ContinuationOptions o;
  o.step = -1;
  try {
    o.validate();
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("continuation.step"), std::string::npos);
  }
}

TEST(Continuation, AllPredictorCorrectorVariantsGiveTheSameDuffingLimitPoints) {
  std::vector<std::vector<double>> lps;
  for (const char* predictor : {"tangent", "secant"}) {
    for (const char* corrector : {"pseudo_arclength", "hypersphere"}) {
      CaseDefinition c = load_case(test::source_path("examples/duffing.toml"), {std::string("continuation.predictor=\"") + predictor + "\"",
                                                                                std::string("continuation.corrector=\"") + corrector + "\"",
                                                                                "continuation.step=0.005", "continuation.step_max=0.005"});
      HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
      const NfrcResult r = compute_nfrc(hbm, c.nfrc, c.outputs);
      ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end) << predictor << "/" << corrector;
      ASSERT_EQ(r.continuation.special_points.size(), 2u) << predictor << "/" << corrector;
      lps.push_back({r.continuation.special_points[0].lambda, r.continuation.special_points[1].lambda});
    }
  }
  // Unlocated limit points sit on a branch point next to the fold: they agree to the omega
  // spacing of points near the fold, which a step of 0.005 keeps below 2e-3.
  for (size_t i = 1; i < lps.size(); ++i) {
    EXPECT_NEAR(lps[i][0], lps[0][0], 2e-3);
    EXPECT_NEAR(lps[i][1], lps[0][1], 2e-3);
  }
}

}  // namespace hbtrack_tests::file_continuation
