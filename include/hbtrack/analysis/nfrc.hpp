#pragma once
// Nonlinear frequency response curve: arc-length continuation of the harmonic balance
// solutions in omega, with the recorded outputs of each point.
#include <functional>
#include <string>
#include <vector>

#include "hbtrack/analysis/stability_monitor.hpp"
#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/hbm/recorded_outputs.hpp"

namespace hbtrack {

struct NfrcOptions {
  double omega_start = 0;  // rad/s
  double omega_end = 0;    // rad/s
  // Displacement unit of the arc-length norm. 0 (default): adaptive, the current amplitude
  // max|x| floored at 1 % of the peak linear response over the range; > 0: this fixed value.
  double length_scale = 0;
  ContinuationOptions continuation;
  StabilityOptions stability;
  void validate() const;
};

// The HBM residual seen by the continuation engine, lambda = omega.
class NfrcProblem final : public ContinuationProblem {
 public:
  // length_scale: the displacement unit of the arc-length norm. When `adaptive`, the unit
  // follows the current amplitude max|u| and length_scale is only its floor.
  NfrcProblem(HarmonicBalance& hbm, double length_scale, double omega_scale, double force_scale, bool adaptive = false)
      : hbm_(hbm), length_scale_(length_scale), omega_scale_(omega_scale), force_scale_(force_scale), adaptive_(adaptive) {}
  int size() const override { return hbm_.unknowns(); }
  void evaluate(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_omega) override {
    hbm_.evaluate(u, omega, r, jacobian, r_omega);
  }
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override {
    const double amplitude = adaptive_ && u.size() ? u.cwiseAbs().maxCoeff() : 0.0;
    return Eigen::VectorXd::Constant(hbm_.unknowns(), std::max(length_scale_, amplitude));
  }
  double parameter_scale() const override { return omega_scale_; }
  double residual_scale() const override { return force_scale_; }
  bool has_corners() const override { return hbm_.has_corners(); }
  bool single_precision_chords() const override { return true; }

 private:
  HarmonicBalance& hbm_;
  double length_scale_, omega_scale_, force_scale_;
  bool adaptive_;
};

// The stability_method of a point whose verdict is that of the evaluated points around it.
inline constexpr const char* kBracketedStability = "bracketed";

// One recorded point of a branch.
struct RecordedPoint {
  double omega = 0;
  std::vector<OutputValues> outputs;  // one per OutputDof
  int stable = -1;                    // 1 stable, 0 unstable, -1 not computed
  double max_floquet_real = 0;        // largest real part of the Floquet exponents (1/s)
  // The Floquet exponents (1/s) and multipliers that decided `stable` (empty when not computed).
  Eigen::VectorXcd floquet_exponents, floquet_multipliers;
  // What decided `stable`: hill | monodromy | shooting, kBracketedStability (the verdict of the
  // evaluated points around it, stability.every_point = false), "" not computed.
  std::string stability_method;
  // The harmonics balanced (multiples of omega / subharmonic): the hK_/phaseK_ columns written.
  std::vector<int> harmonic_numbers;
  int subharmonic = 1;
  // An adaptive run's (analysis/adaptive_nfrc.hpp): the H this point was balanced with; the
  // harmonic_numbers above it hold zeros. 0: the run's one H.
  int balanced_harmonics = 0;
};

RecordedPoint record_point(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, const std::vector<OutputDof>& outputs);

// Scales used by NfrcProblem, from the case: peak linear response and forcing norm.
double automatic_length_scale(HarmonicBalance& hbm, double omega_start, double omega_end);
double force_scale(HarmonicBalance& hbm, double length_scale);

struct NfrcResult {
  ContinuationResult continuation;
  std::vector<RecordedPoint> recorded;
  double length_scale = 0;
  double stability_s = 0;  // of continuation.summary.wall_s, the time spent on stability
};

// Called for each accepted point with its recorded outputs; return false to stop.
using RecordedObserver = std::function<bool(const BranchPoint&, const RecordedPoint&, int)>;

// restart: resume from a saved state and/or save it between steps (see continue_within).
NfrcResult compute_nfrc(HarmonicBalance& hbm, const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                        const RecordedObserver& observer = {}, const ContinuationRestart& restart = {});

// The branch through a given solution (x0, omega0), within a window of omega: e.g. an isolated
// branch from one of its limit points, until it closes (window.stop_when_closed). Scales and
// stability as compute_nfrc, from options (its omega range sets the arc-length units).
NfrcResult compute_branch(HarmonicBalance& hbm, const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                          const Eigen::VectorXd& x0, double omega0, const ParameterWindow& window, const RecordedObserver& observer = {},
                          const ContinuationRestart& restart = {});

// A first point for Newton at fixed omega: the linear solution when Newton converges from it,
// otherwise the solution linearised about rest (HarmonicBalance::rest_linearized_solution), which
// starts a stiff stuck friction element or a preloaded contact near its branch.
// `lambda` is the problem's parameter at that point (omega itself for an NFRC).
Eigen::VectorXd starting_guess(HarmonicBalance& hbm, ContinuationProblem& problem, double omega, double lambda, double tolerance,
                               int max_iterations);

// One periodic solution at fixed omega, by Newton from the linear solution (or from `guess`).
struct FixedFrequencySolution {
  bool converged = false;
  int newton_iterations = 0;
  Eigen::VectorXd x;
  RecordedPoint recorded;
};
FixedFrequencySolution solve_at_frequency(HarmonicBalance& hbm, double omega, const std::vector<OutputDof>& outputs, double tolerance,
                                          int max_iterations, const Eigen::VectorXd* guess = nullptr);

}  // namespace hbtrack
