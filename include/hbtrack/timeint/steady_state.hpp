#pragma once
// Integration to the periodic steady state, period by period, with stroboscopic detection: the
// state s = (x, v / omega) at the start of consecutive periods is compared in the max-norm,
//   change_k = ||s(t_{k+1}) - s(t_k)||_inf / max over period k of ||s(t)||_inf,
// and the motion is periodic when change_k <= tolerance, without growing, for `confirmations`
// consecutive periods. Starting on an HBM solution puts the motion within the HBM truncation
// error of a periodic orbit: if that orbit is unstable the change starts small but grows by the
// largest Floquet multiplier each period (1.33 per period on the Duffing middle branch, from
// 5e-8 with dopri5), and that growth is what tells it from a stable orbit. Growth below 1 % of
// the tolerance is taken for round-off noise (1e-12 with dopri5, less with newmark), so a start
// closer than that to an unstable orbit can pass for periodic: ask a stability analysis then.
// Dividing the velocity by omega puts both halves of the state in displacement units. After
// convergence, the transient left is about change_k / (1 - |lambda|) for the slowest decaying
// Floquet multiplier lambda.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "hbtrack/hbm/recorded_outputs.hpp"
#include "hbtrack/timeint/period_summary.hpp"
#include "hbtrack/timeint/time_integrator.hpp"

namespace hbtrack {

struct SteadyStateOptions {
  double tolerance = 1e-6;  // on change_k
  int confirmations = 3;    // consecutive periods with change_k <= tolerance, not growing
  int max_periods = 2000;   // period budget
  int record_periods = 1;   // periods of output signals kept (the last ones)
  int harmonics = 7;        // Fourier coefficients of the last period, up to this order
  void validate() const;    // throws std::invalid_argument naming the field
};

struct SteadyStateResult {
  bool converged = false;
  // converged | max_periods | interrupted | diverged (non-finite, or 1e8 times the size of the
  // first period), or the integrator's failure reason (newton_failure, integration_failure).
  StopReason stop_reason = StopReason::running;
  std::string message;                 // one line, for failures
  int periods = 0;                     // periods integrated
  double last_change = 0;              // change_k of the last period
  Eigen::VectorXd time;                // instants of the recorded periods
  Eigen::MatrixXd signals;             // time.size() x outputs: displacement of each output dof
  std::vector<PeriodSummary> outputs;  // of the last period, one per output dof
  MotionState final_state;
  IntegrationStatistics statistics;
};

// Called after each period with its index (from 0) and change; return false to stop
// ("interrupted").
using PeriodObserver = std::function<bool(int period, double change)>;

// Starts `integrator` from `initial` and integrates until the steady state, the budget or a
// failure. Needs integrator.samples_per_period() >= 2 harmonics + 1.
SteadyStateResult integrate_to_steady_state(TimeIntegrator& integrator, const MotionState& initial, const std::vector<OutputDof>& outputs,
                                            const SteadyStateOptions& options, const PeriodObserver& observer = {});

}  // namespace hbtrack
