#pragma once
// What the steady-state driver needs from a time integrator of an EquationOfMotion: start from
// a state, then advance one forcing period at a time, reporting the state at equally spaced
// instants of the period. Period k starts at t = t_start + k T exactly (no accumulated drift),
// so the samples are phase-locked to the forcing.
#include <Eigen/Dense>
#include <functional>
#include <string>

#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack {

struct MotionState {
  double time = 0;
  Eigen::VectorXd x, v;  // displacements and velocities of every dof
  // Internal variables of the history elements (EquationOfMotion::history); empty: at rest.
  Eigen::VectorXd history{};
};

// Work counters, for comparing methods.
struct IntegrationStatistics {
  long steps = 0;              // accepted time steps
  long force_evaluations = 0;  // evaluations of f_nl (each with tangents for Newmark)
  long newton_iterations = 0;  // implicit methods only
};

// Sees the state at sample `index` (0 = the period's start) of the current period.
using SampleObserver = std::function<void(int index, const MotionState& state)>;

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  virtual std::string method() const = 0;
  virtual const EquationOfMotion& equation() const = 0;
  // Instants reported per period: t0 + i T / samples_per_period(), i = 0 .. samples - 1.
  virtual int samples_per_period() const = 0;
  // (Re)starts the integration from `initial` (its time is the first period's start).
  virtual void start(const MotionState& initial) = 0;
  // Integrates over one period from state(). Returns false when the step failed; then
  // failure() holds the stop reason and a one-line explanation.
  virtual bool advance_period(const SampleObserver& observe) = 0;
  // The state at the start of the next period (after advance_period), or the initial state.
  virtual const MotionState& state() const = 0;
  virtual const IntegrationStatistics& statistics() const = 0;

  struct Failure {
    StopReason reason = StopReason::running;  // diverged, newton_failure, integration_failure
    std::string message;                      // one line
  };
  const Failure& failure() const { return failure_; }

 protected:
  Failure failure_;
};

}  // namespace hbtrack
