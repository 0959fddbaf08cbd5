#include "hbtrack/analysis/nfrc.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hbtrack {

void NfrcOptions::validate() const {
  if (!std::isfinite(omega_start) || omega_start < 0) throw std::invalid_argument("continuation.omega_start: must be finite and >= 0");
  if (!std::isfinite(omega_end) || omega_end < 0) throw std::invalid_argument("continuation.omega_end: must be finite and >= 0");
  if (omega_end == omega_start) throw std::invalid_argument("continuation.omega_end: must differ from omega_start");
  if (!std::isfinite(length_scale) || length_scale < 0) throw std::invalid_argument("continuation.length_scale: must be >= 0");
  continuation.validate();
  stability.validate();
}

RecordedPoint record_point(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, const std::vector<OutputDof>& outputs) {
  RecordedPoint p;
  p.omega = omega;
  p.harmonic_numbers = hbm.basis().harmonic_numbers();
  p.subharmonic = hbm.subharmonic();
  if (outputs.empty()) return p;
  const Eigen::VectorXd full = hbm.expand(x, omega);
  const int samples = std::max(hbm.basis().samples(), 256);
  for (const OutputDof& o : outputs) {
    p.outputs.push_back(output_values(full, hbm.model().dofs(), hbm.basis().harmonics(), o.dof, samples));
    // h1 is the harmonic at omega: basis harmonic nu (the extremes are over the whole period).
    p.outputs.back().h1 =
        hbm.subharmonic() <= hbm.basis().harmonics() ? harmonic_magnitude(p.outputs.back().harmonics, hbm.subharmonic()) : 0.0;
  }
  return p;
}

double automatic_length_scale(HarmonicBalance& hbm, double omega_start, double omega_end) {
  // The largest linear response on the retained dofs over the range sets the displacement unit.
  double peak = 0;
  constexpr int grid = 64;
  for (int i = 0; i <= grid; ++i) {
    const double omega = omega_start + (omega_end - omega_start) * i / grid;
    const Eigen::VectorXd x = hbm.linear_solution(omega);
    if (x.allFinite()) peak = std::max(peak, x.cwiseAbs().maxCoeff());
  }
  return peak > 0 ? peak : 1.0;
}

double force_scale(HarmonicBalance& hbm, double length_scale) {
  double unit = 0;
  for (const HarmonicForce& f : hbm.model().forcing)
    unit = std::max({unit, f.cos_part.cwiseAbs().maxCoeff(), f.sin_part.cwiseAbs().maxCoeff()});
  const double amplitude = std::abs(hbm.parameters().value(hbm.amplitude_parameter()));
  if (unit * amplitude > 0) return unit * amplitude;
  if (unit > 0) return unit;
  return hbm.model().stiffness.cwiseAbs().maxCoeff() * length_scale;
}

Eigen::VectorXd starting_guess(HarmonicBalance& hbm, ContinuationProblem& problem, double omega, double lambda, double tolerance,
                               int max_iterations) {
  const Eigen::VectorXd linear = hbm.linear_solution(omega);
  Eigen::VectorXd trial = linear;
  if (newton_at_fixed_parameter(problem, trial, lambda, tolerance, max_iterations) >= 0) return linear;
  const Eigen::VectorXd rest = hbm.rest_linearized_solution(omega);
  return rest.allFinite() ? rest : linear;
}

NfrcResult compute_nfrc(HarmonicBalance& hbm, const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                        const RecordedObserver& observer, const ContinuationRestart& restart) {
  const ParameterWindow window{std::min(options.omega_start, options.omega_end), std::max(options.omega_start, options.omega_end),
                               options.omega_end >= options.omega_start ? 1 : -1, false};
  Eigen::VectorXd guess;
  if (!restart.resume_from) {
    const double reference =
        options.length_scale == 0 ? automatic_length_scale(hbm, options.omega_start, options.omega_end) : options.length_scale;
    NfrcProblem problem(hbm, reference, 1.0, force_scale(hbm, reference));
    guess = starting_guess(hbm, problem, options.omega_start, options.omega_start, options.continuation.tolerance,
                           3 * options.continuation.max_iterations);
  }
  return compute_branch(hbm, options, outputs, guess, options.omega_start, window, observer, restart);
}

NfrcResult compute_branch(HarmonicBalance& hbm, const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                          const Eigen::VectorXd& x0, double omega0, const ParameterWindow& window, const RecordedObserver& observer,
                          const ContinuationRestart& restart) {
  options.validate();
  NfrcResult result;
  const bool adaptive = options.length_scale == 0;
  const double reference = adaptive ? automatic_length_scale(hbm, options.omega_start, options.omega_end) : options.length_scale;
  result.length_scale = adaptive ? 0.01 * reference : reference;
  NfrcProblem problem(hbm, result.length_scale, std::abs(options.omega_end - options.omega_start), force_scale(hbm, reference), adaptive);
  FloquetMonitor monitor(hbm, options.stability);
  // Of the last point passed on: a point the monitor skipped shares it. A resumed run's first
  // points may have been skipped: the saved state carries the verdict of its last point.
  int last_stable = -1;
  if (restart.resume_from && !restart.resume_from->earlier_test_values.empty())
    last_stable = restart.resume_from->monitor_verdict % 2 == 0 ? 1 : 0;
  result.continuation = continue_within(
      problem, x0, omega0, window, options.continuation,
      [&](const BranchPoint& p, int index) {
        RecordedPoint rec = record_point(hbm, p.u, p.lambda, outputs);
        if (options.stability.enabled() && !p.monitored) {
          // Between two evaluated points whose verdicts agree (the engine evaluates every point
          // between two that disagree): their verdict, no exponents of its own.
          rec.stable = last_stable;
          rec.max_floquet_real = NAN;
          rec.stability_method = kBracketedStability;
        } else if (options.stability.enabled()) {
          const FloquetResult& f = monitor.result_for(p);
          rec.stable = f.stable ? 1 : 0;
          rec.max_floquet_real = f.max_real;
          rec.floquet_exponents = f.exponents;
          rec.floquet_multipliers = f.multipliers;
          rec.stability_method = to_string(f.method);
        }
        last_stable = rec.stable;
        result.recorded.push_back(std::move(rec));
        return !observer || observer(p, result.recorded.back(), index);
      },
      options.stability.enabled() ? &monitor : nullptr, restart);
  result.stability_s = monitor.seconds();
  return result;
}

FixedFrequencySolution solve_at_frequency(HarmonicBalance& hbm, double omega, const std::vector<OutputDof>& outputs, double tolerance,
                                          int max_iterations, const Eigen::VectorXd* guess) {
  FixedFrequencySolution s;
  const double length = automatic_length_scale(hbm, omega, omega);
  NfrcProblem problem(hbm, length, std::max(omega, 1.0), force_scale(hbm, length));
  s.x = guess ? *guess : starting_guess(hbm, problem, omega, omega, tolerance, max_iterations);
  s.newton_iterations = newton_at_fixed_parameter(problem, s.x, omega, tolerance, max_iterations);
  s.converged = s.newton_iterations >= 0;
  if (s.converged) s.recorded = record_point(hbm, s.x, omega, outputs);
  return s;
}

}  // namespace hbtrack
