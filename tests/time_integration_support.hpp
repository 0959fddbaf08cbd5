#pragma once
// Time integration of a case started on its harmonic-balance orbit, for the tests that check an
// orbit against the equation of motion.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>

#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/timeint/initial_state.hpp"
#include "hbtrack/timeint/newmark_integrator.hpp"
#include "hbtrack/timeint/steady_state.hpp"

namespace hbtrack::test {

// The largest deviation, relative to the orbit's range, between Newmark's last period started
// on the HBM orbit and that orbit, over the case's outputs.
inline double deviation_from_time_integration(const CaseDefinition& c, HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega,
                                              int harmonics, int steps) {
  const int n = c.model.dofs();
  const Eigen::VectorXd full = hbm.expand(x, omega);
  EquationOfMotion eom(c.model, c.elements, hbm.parameters(), omega);
  MotionState start = state_from_harmonics(full, n, harmonics, omega);
  start.history = eom.periodic_history(period_samples(full, n, harmonics, hbm.basis().samples()));
  NewmarkOptions options;
  options.steps_per_period = steps;
  NewmarkIntegrator integrator(eom, options);
  SteadyStateOptions steady;
  steady.harmonics = harmonics;
  const SteadyStateResult r = integrate_to_steady_state(integrator, start, c.outputs, steady);
  EXPECT_TRUE(r.converged) << "omega " << omega << ": " << to_string(r.stop_reason);
  const Eigen::MatrixXd orbit = period_samples(full, n, harmonics, steps);
  double worst = 0;
  for (size_t o = 0; o < c.outputs.size(); ++o) {
    const Eigen::VectorXd expected = orbit.col(c.outputs[o].dof);
    worst = std::max(worst, (r.signals.col(static_cast<Eigen::Index>(o)) - expected).cwiseAbs().maxCoeff() /
                                (expected.maxCoeff() - expected.minCoeff()));
  }
  return worst;
}

}  // namespace hbtrack::test
