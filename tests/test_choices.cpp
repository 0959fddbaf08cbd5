// The settings' choices (util/choices.hpp): every value's name parses back to it, the names are
// the ones the case file, summary.json and Python use, and an unknown name gives the one-line
// message naming the field and every allowed name.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "choice_round_trip.hpp"
#include "hbtrack/util/choices.hpp"
#include "hbtrack/util/stop_reason.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_choices {

using namespace hbtrack;

// The names are a file format: these lists are what existing case files and results hold.
TEST(Choices, EveryValueRoundTripsThroughItsName) {
  EXPECT_EQ(round_trip_names<Predictor>(), (std::vector<std::string>{"tangent", "secant"}));
  EXPECT_EQ(round_trip_names<Corrector>(), (std::vector<std::string>{"pseudo_arclength", "hypersphere"}));
  EXPECT_EQ(round_trip_names<Condensation>(), (std::vector<std::string>{"auto", "schur", "modal", "none"}));
  EXPECT_EQ(round_trip_names<StabilityMethod>(), (std::vector<std::string>{"hill", "monodromy", "shooting", "none"}));
  EXPECT_EQ(round_trip_names<HillSolver>(), (std::vector<std::string>{"auto", "dense", "arnoldi"}));
  EXPECT_EQ(round_trip_names<CrossCheck>(), (std::vector<std::string>{"auto", "off"}));
  EXPECT_EQ(round_trip_names<TrackingMethod>(), (std::vector<std::string>{"bordered", "extended"}));
  EXPECT_EQ(round_trip_names<IntegrationMethod>(), (std::vector<std::string>{"newmark", "dopri5"}));
  EXPECT_EQ(round_trip_names<BaseMotionKind>(), (std::vector<std::string>{"displacement", "velocity", "acceleration"}));
  // Not a setting, but named the same way: summary.json's and the checkpoints' stop_reason.
  EXPECT_EQ(round_trip_names<StopReason>(), (std::vector<std::string>{"running",
                                                                      "reached_end",
                                                                      "left_range",
                                                                      "closed",
                                                                      "max_points",
                                                                      "step_size_underflow",
                                                                      "step_size_underflow_on_curvature",
                                                                      "interrupted",
                                                                      "time_limit",
                                                                      "no_convergence_at_start",
                                                                      "rejoined",
                                                                      "strong_resonance",
                                                                      "not_started",
                                                                      "completed",
                                                                      "converged",
                                                                      "max_periods",
                                                                      "diverged",
                                                                      "newton_failure",
                                                                      "integration_failure",
                                                                      "no_convergence",
                                                                      "tasks_failed",
                                                                      "checks_failed",
                                                                      "stopped_by_callback",
                                                                      "reached_ns_point"}));
}

TEST(Choices, TheNamedParsersAgreeWithTheTables) {
  EXPECT_EQ(parse_predictor("secant"), Predictor::secant);
  EXPECT_EQ(parse_corrector("hypersphere"), Corrector::hypersphere);
  EXPECT_EQ(parse_condensation("auto"), Condensation::automatic);
  EXPECT_EQ(parse_stability_method("none"), StabilityMethod::none);
  EXPECT_EQ(parse_hill_solver("arnoldi"), HillSolver::arnoldi);
  EXPECT_EQ(parse_cross_check("off"), CrossCheck::off);
  EXPECT_EQ(parse_tracking_method("extended"), TrackingMethod::extended);
  EXPECT_EQ(parse_integration_method("dopri5"), IntegrationMethod::dopri5);
  EXPECT_EQ(parse_stop_reason("step_size_underflow_on_curvature"), StopReason::step_size_underflow_on_curvature);
}

// The messages the case file, the CLI and Python report (tests/test_case_file.cpp and
// python/tests/test_errors.py match them).
TEST(Choices, AnUnknownNameNamesTheFieldAndEveryAllowedName) {
  EXPECT_EQ(error_for<Predictor>("euler"), "continuation.predictor: must be tangent or secant, got 'euler'");
  EXPECT_EQ(error_for<Corrector>("newton"), "continuation.corrector: must be pseudo_arclength or hypersphere, got 'newton'");
  EXPECT_EQ(error_for<Condensation>("guyan"), "harmonic_balance.condensation: must be auto, schur, modal or none, got 'guyan'");
  EXPECT_EQ(error_for<StabilityMethod>("floquet"), "stability.method: must be hill, monodromy, shooting or none, got 'floquet'");
  EXPECT_EQ(error_for<HillSolver>("qr"), "stability.hill_solver: must be auto, dense or arnoldi, got 'qr'");
  EXPECT_EQ(error_for<CrossCheck>("on"), "stability.cross_check: must be auto or off, got 'on'");
  EXPECT_EQ(error_for<TrackingMethod>("minimal"), "tracking method: must be bordered or extended, got 'minimal'");
  EXPECT_EQ(error_for<IntegrationMethod>("rk4"), "method: must be newmark or dopri5, got 'rk4'");
  EXPECT_EQ(error_for<StopReason>("finished").substr(0, 42), "stop_reason: must be running, reached_end,");
  EXPECT_NE(error_for<StopReason>("finished").find(" or reached_ns_point, got 'finished'"), std::string::npos);
  // Names are exact: no case folding, no surrounding blanks.
  EXPECT_NE(error_for<Predictor>("Tangent"), "no error");
  EXPECT_NE(error_for<Predictor>(" tangent"), "no error");
  EXPECT_NE(error_for<Condensation>("automatic"), "no error");
}

TEST(Choices, ACallerMayNameTheFieldItsOwnWay) {
  try {
    parse_choice<TrackingMethod>("minimal", "--method");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--method: must be bordered or extended, got 'minimal'");
  }
}

}  // namespace hbtrack_tests::file_choices
