#pragma once
// Nonlinear modes by the extended periodic motion concept (EPMC; Krack, Computers & Structures
// 154, 2015): the forcing is replaced by a negative modal damping term -xi M x', which makes
// the damped free motion periodic, so that omega(a) is the backbone and xi(a) the amplitude-
// dependent modal damping. Harmonic balance of
//   M x'' + (C - xi M) x' + K x + f_nl(x, x') = 0,   x = a psi,
// with psi normalised (first-harmonic modal mass psi_1^T M psi_1 = 1) and its phase fixed (the
// sine part of harmonic 1 orthogonal in M to the linear mode). Unknowns [psi; omega; xi],
// continuation parameter lambda = log10(a): the same engine as the NFRC.
#include <functional>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"

namespace hbtrack {

struct BackboneOptions {
  int mode = 1;                // linear mode followed, from 1 (ascending frequency)
  double amplitude_start = 0;  // modal amplitude a: from the nearly linear mode at this value
  double amplitude_end = 0;    // up to this one
  ContinuationOptions continuation;
  void validate() const;  // throws std::invalid_argument naming the field
};

// The EPMC residual on every dof (the harmonic balance system must be built with
// condensation "none"). It evaluates its own copy of hbm with the forcing switched off
// (amplitude = 0): the negative damping replaces it.
class EpmcProblem final : public ContinuationProblem {
 public:
  // mode: mass-normalised linear mode shape (phase reference); scales of psi, omega, xi.
  EpmcProblem(const HarmonicBalance& hbm, const Eigen::VectorXd& mode, double psi_scale, double omega_scale, double xi_scale,
              double log_amplitude_scale, double residual_scale);
  int size() const override { return hbm_.unknowns() + 2; }
  void evaluate(const Eigen::VectorXd& u, double lambda, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_lambda) override;
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override;
  double parameter_scale() const override { return log_amplitude_scale_; }
  double residual_scale() const override { return residual_scale_; }

 private:
  // out = (nabla x M) psi: the velocity coefficients at unit frequency, times M.
  void mass_derivative(const Eigen::VectorXd& psi, Eigen::VectorXd& out) const;

  HarmonicBalance hbm_;
  Eigen::VectorXd mode_m_;  // M * mode
  int first_cosine_ = 1;    // coefficient index of harmonic 1's cosine
  double psi_scale_, omega_scale_, xi_scale_, log_amplitude_scale_, residual_scale_;
  Eigen::VectorXd r_hb_, r_omega_, dpsi_;
  Eigen::MatrixXd j_hb_;
};

struct BackbonePoint {
  double amplitude = 0;                    // a: sqrt(x_1^T M x_1), the first harmonic's modal amplitude
  double omega = 0;                        // rad/s
  double xi = 0;                           // the EPMC damping coefficient (1/s)
  double damping_ratio = 0;                // xi / (2 omega)
  RecordedPoint recorded;                  // the outputs of x = a psi
  std::vector<Eigen::VectorXd> harmonics;  // per output: harmonic_magnitude j = 0..H (0: the mean a0/2)
};

struct BackboneResult {
  ContinuationResult continuation;  // lambda = log10(a), u = [psi; omega; xi]
  std::vector<BackbonePoint> points;
  double linear_omega = 0, linear_xi = 0;  // of the linear mode the branch starts from
};

using BackboneObserver = std::function<bool(const BranchPoint&, const BackbonePoint&, int)>;

// The backbone of `options.mode`. Sets the system's amplitude parameter to 0 (no forcing).
// Throws std::invalid_argument for bad options or a condensed system, std::runtime_error when
// Newton fails at the start (amplitude_start too large for the linear mode to be a guess).
BackboneResult compute_backbone(const HarmonicBalance& hbm, const BackboneOptions& options, const std::vector<OutputDof>& outputs,
                                const BackboneObserver& observer = {});

// A point of the result's branch as recorded (outputs from x = a psi).
BackbonePoint backbone_point(HarmonicBalance& hbm, const Eigen::VectorXd& u, double lambda, const std::vector<OutputDof>& outputs);

}  // namespace hbtrack
