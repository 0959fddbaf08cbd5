#include "hbtrack/timeint/steady_state.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

namespace hbtrack {

void SteadyStateOptions::validate() const {
  if (!(tolerance > 0)) throw std::invalid_argument("tolerance: must be > 0");
  if (confirmations < 1) throw std::invalid_argument("confirmations: must be >= 1, got " + std::to_string(confirmations));
  if (max_periods < 1) throw std::invalid_argument("max_periods: must be >= 1, got " + std::to_string(max_periods));
  if (record_periods < 1) throw std::invalid_argument("record_periods: must be >= 1, got " + std::to_string(record_periods));
  if (harmonics < 0) throw std::invalid_argument("harmonics: must be >= 0, got " + std::to_string(harmonics));
}

namespace {

constexpr double kNoiseFraction = 0.01;
constexpr double kBlowUpFactor = 1e8;

// ||(x, v / omega)||_inf: the state's size in displacement units.
double state_norm(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double omega) {
  return std::max(x.lpNorm<Eigen::Infinity>(), v.lpNorm<Eigen::Infinity>() / omega);
}

// Output displacements of one period: samples x outputs, with the sample instants.
struct PeriodRecord {
  Eigen::VectorXd time;
  Eigen::MatrixXd values;
};

}  // namespace

SteadyStateResult integrate_to_steady_state(TimeIntegrator& integrator, const MotionState& initial, const std::vector<OutputDof>& outputs,
                                            const SteadyStateOptions& options, const PeriodObserver& observer) {
  options.validate();
  const int samples = integrator.samples_per_period();
  if (samples < 2 * options.harmonics + 1)
    throw std::invalid_argument("samples per period: must be >= 2*harmonics+1 = " + std::to_string(2 * options.harmonics + 1) + ", got " +
                                std::to_string(samples));
  const int n = integrator.equation().dofs();
  for (const OutputDof& o : outputs)
    if (o.dof < 0 || o.dof >= n) throw std::invalid_argument("output " + o.name + ": dof index out of range");
  const double omega = integrator.equation().omega();
  const Eigen::Index columns = static_cast<Eigen::Index>(outputs.size());

  SteadyStateResult result;
  integrator.start(initial);
  std::deque<PeriodRecord> recorded;  // the last record_periods periods
  PeriodRecord current;
  double period_scale = 0;  // max of the state norm over the current period
  double first_scale = 0;   // the same over the first period (and the initial state)
  int confirmed = 0;
  const SampleObserver observe = [&](int i, const MotionState& s) {
    current.time(i) = s.time;
    for (Eigen::Index c = 0; c < columns; ++c) current.values(i, c) = s.x(outputs[static_cast<size_t>(c)].dof);
    period_scale = std::max(period_scale, state_norm(s.x, s.v, omega));
  };

  result.stop_reason = StopReason::max_periods;
  while (result.periods < options.max_periods) {
    const MotionState start = integrator.state();
    current.time.resize(samples);
    current.values.resize(samples, columns);
    period_scale = 0;
    if (!integrator.advance_period(observe)) {
      result.stop_reason = integrator.failure().reason;
      result.message = integrator.failure().message;
      break;
    }
    ++result.periods;
    const MotionState& end = integrator.state();
    if (result.periods == 1) first_scale = std::max(period_scale, state_norm(initial.x, initial.v, omega));
    // A forced damped motion grows by bounded factors; this much growth is a numerical blow-up
    // (kept out of the records, whose values would be meaningless).
    if (!end.x.allFinite() || !end.v.allFinite() || !(period_scale <= kBlowUpFactor * first_scale)) {
      result.stop_reason = StopReason::diverged;
      result.message = "the state blew up (non-finite or 1e8 times its first period's size) in period " + std::to_string(result.periods);
      break;
    }
    recorded.push_back(current);
    if (static_cast<int>(recorded.size()) > options.record_periods) recorded.pop_front();

    const double change = state_norm(end.x - start.x, end.v - start.v, omega);
    const double previous_change = result.last_change;
    result.last_change = period_scale > 0 ? change / period_scale : 0.0;
    // A small change that grows is a departure from an unstable orbit that has only begun
    // (a start on an HBM solution); below 1 % of the tolerance the change is round-off noise
    // and its growth means nothing.
    const bool small = result.last_change <= options.tolerance;
    const bool growing =
        result.periods > 1 && result.last_change > previous_change && result.last_change > kNoiseFraction * options.tolerance;
    confirmed = small && !growing ? confirmed + 1 : 0;
    if (confirmed >= options.confirmations) {
      result.converged = true;
      result.stop_reason = StopReason::converged;
      break;
    }
    if (observer && !observer(result.periods - 1, result.last_change)) {
      result.stop_reason = StopReason::interrupted;
      break;
    }
  }

  result.final_state = integrator.state();
  result.statistics = integrator.statistics();
  const Eigen::Index rows = static_cast<Eigen::Index>(recorded.size()) * samples;
  result.time.resize(rows);
  result.signals.resize(rows, columns);
  Eigen::Index row = 0;
  for (const PeriodRecord& p : recorded) {
    result.time.segment(row, samples) = p.time;
    result.signals.middleRows(row, samples) = p.values;
    row += samples;
  }
  if (!recorded.empty())
    for (Eigen::Index c = 0; c < columns; ++c) result.outputs.push_back(summarise_period(recorded.back().values.col(c), options.harmonics));
  return result;
}

}  // namespace hbtrack
