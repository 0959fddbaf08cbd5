#include "hbtrack/analysis/parameter_continuation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hbtrack/analysis/stability_monitor.hpp"

namespace hbtrack {

ParameterProblem::ParameterProblem(const HarmonicBalance& hbm, int parameter, double omega, double length_scale, double parameter_scale,
                                   double force_scale)
    : hbm_(hbm),
      parameter_(parameter),
      omega_(omega),
      length_scale_(length_scale),
      parameter_scale_(parameter_scale),
      force_scale_(force_scale) {
  if (parameter < 0 || parameter >= hbm.parameters().size()) throw std::invalid_argument("parameter index out of range");
}

void ParameterProblem::evaluate(const Eigen::VectorXd& u, double p, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_p) {
  hbm_.set_parameter(parameter_, p);
  hbm_.evaluate(u, omega_, r, jacobian, nullptr);
  if (r_p) *r_p = hbm_.parameter_derivative(u, omega_, parameter_);
}

Eigen::VectorXd ParameterProblem::unknown_scale(const Eigen::VectorXd& u) const {
  const double amplitude = u.size() ? u.cwiseAbs().maxCoeff() : 0.0;
  return Eigen::VectorXd::Constant(hbm_.unknowns(), std::max(length_scale_, amplitude));
}

namespace {

// Floquet stability and the PD/NS test functions along a parameter branch: the frequency is
// fixed and the branch's lambda is the parameter, set before each evaluation (of its own copy).
class ParameterFloquetMonitor final : public BranchMonitor {
 public:
  ParameterFloquetMonitor(const HarmonicBalance& hbm, int parameter, double omega, StabilityOptions options)
      : hbm_(hbm), parameter_(parameter), omega_(omega), options_(std::move(options)) {}
  std::vector<SpecialPointType> types() const override { return {SpecialPointType::period_doubling, SpecialPointType::neimark_sacker}; }
  std::vector<double> test_functions(const BranchPoint& p) override {
    const FloquetResult& r = result_for(p);
    return {period_doubling_test(r.multipliers), neimark_sacker_test(r.multipliers)};
  }
  // Tolerances of FloquetMonitor::confirm (stability_monitor.hpp).
  bool confirm(SpecialPointType type, const BranchPoint& p, bool located) override {
    return has_multiplier_on_unit_circle(result_for(p).multipliers, type, located ? 1e-3 : 0.05);
  }
  const FloquetResult& result_for(const BranchPoint& p) {
    for (auto it = recent_.rbegin(); it != recent_.rend(); ++it)
      if (it->lambda == p.lambda && it->u.size() == p.u.size() && it->u == p.u) return it->result;
    if (recent_.size() >= 8) recent_.erase(recent_.begin());
    hbm_.set_parameter(parameter_, p.lambda);
    recent_.push_back({p.lambda, p.u, floquet(hbm_, p.u, omega_, options_)});
    return recent_.back().result;
  }

 private:
  struct Entry {
    double lambda;
    Eigen::VectorXd u;
    FloquetResult result;
  };
  HarmonicBalance hbm_;
  int parameter_;
  double omega_;
  StabilityOptions options_;
  std::vector<Entry> recent_;
};

}  // namespace

ParameterBranchResult continue_in_parameter(const HarmonicBalance& caller, int parameter, double omega, double start, double end,
                                            const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                                            const ParameterObserver& observer) {
  if (parameter < 0 || parameter >= caller.parameters().size()) throw std::invalid_argument("parameter index out of range");
  if (!(omega > 0) || !std::isfinite(omega)) throw std::invalid_argument("omega: must be > 0 and finite");
  if (!std::isfinite(start) || !std::isfinite(end) || start == end) throw std::invalid_argument("range: must be finite with LO != HI");
  options.continuation.validate();
  options.stability.validate();
  HarmonicBalance hbm(caller);  // at the parameter value each step needs
  // Units: the larger linear response and forcing of the range's two ends (the amplitude may
  // be zero at one of them), adaptive as the NFRC's unless the case fixes length_scale.
  double reference = options.length_scale, forcing = 0;
  for (const double p : {start, end}) {
    hbm.set_parameter(parameter, p);
    if (options.length_scale == 0) reference = std::max(reference, automatic_length_scale(hbm, omega, omega));
    forcing = std::max(forcing, force_scale(hbm, reference > 0 ? reference : 1.0));
  }
  if (!(reference > 0)) reference = 1.0;
  ParameterBranchResult result;
  result.length_scale = options.length_scale == 0 ? 0.01 * reference : reference;
  ParameterProblem problem(hbm, parameter, omega, result.length_scale, std::abs(end - start), forcing);

  hbm.set_parameter(parameter, start);
  Eigen::VectorXd x0 = starting_guess(hbm, problem, omega, start, options.continuation.tolerance, 4 * options.continuation.max_iterations);
  result.start_newton_iterations =
      newton_at_fixed_parameter(problem, x0, start, options.continuation.tolerance, 4 * options.continuation.max_iterations);
  if (result.start_newton_iterations < 0)
    throw std::runtime_error("Newton did not converge at the start of the range (parameter = " + std::to_string(start) + ")");

  ParameterFloquetMonitor monitor(hbm, parameter, omega, options.stability);
  const ParameterWindow window{std::min(start, end), std::max(start, end), end > start ? 1 : -1, false};
  result.continuation = continue_within(
      problem, x0, start, window, options.continuation,
      [&](const BranchPoint& p, int index) {
        hbm.set_parameter(parameter, p.lambda);
        ParameterBranchPoint point{p.lambda, record_point(hbm, p.u, omega, outputs)};
        if (options.stability.enabled()) {
          const FloquetResult& f = monitor.result_for(p);
          point.recorded.stable = f.stable ? 1 : 0;
          point.recorded.max_floquet_real = f.max_real;
        }
        result.points.push_back(std::move(point));
        return !observer || observer(p, result.points.back(), index);
      },
      options.stability.enabled() ? &monitor : nullptr);
  return result;
}

}  // namespace hbtrack
