#include "hbtrack/analysis/backbone.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "hbtrack/model/damping.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

void BackboneOptions::validate() const {
  if (mode < 1) throw std::invalid_argument("mode: must be >= 1, got " + std::to_string(mode));
  if (!(amplitude_start > 0) || !std::isfinite(amplitude_start)) throw std::invalid_argument("range: LO must be a finite amplitude > 0");
  if (!(amplitude_end > amplitude_start) || !std::isfinite(amplitude_end)) throw std::invalid_argument("range: HI must be finite and > LO");
  continuation.validate();
}

EpmcProblem::EpmcProblem(const HarmonicBalance& hbm, const VectorXd& mode, double psi_scale, double omega_scale, double xi_scale,
                         double log_amplitude_scale, double residual_scale)
    : hbm_(hbm.with_parameter(hbm.amplitude_parameter(), 0.0)),
      mode_m_(hbm.model().mass * mode),
      psi_scale_(psi_scale),
      omega_scale_(omega_scale),
      xi_scale_(xi_scale),
      log_amplitude_scale_(log_amplitude_scale),
      residual_scale_(residual_scale) {
  if (hbm.retained_dofs() != hbm.model().dofs())
    throw std::invalid_argument("backbone: needs every dof as unknown (harmonic_balance.condensation = \"none\")");
  first_cosine_ = hbm.basis().cosine_index(1);
  if (first_cosine_ < 0 || hbm.subharmonic() != 1)
    throw std::invalid_argument(
        "backbone: needs harmonic 1 among harmonic_balance.harmonics (the mode's amplitude and phase are its), and subharmonic = 1");
}

void EpmcProblem::mass_derivative(const VectorXd& psi, VectorXd& out) const {
  const int n = hbm_.retained_dofs();
  const MatrixXd& m = hbm_.model().mass;
  out.setZero(psi.size());
  const FourierBasis& basis = hbm_.basis();
  for (int c = 0; c < basis.coefficients(); ++c) {
    const int j = basis.harmonic_of(c);
    if (j == 0 || basis.is_sine(c)) continue;
    // x = a cos + b sin  ->  x' (unit frequency) = j b cos - j a sin
    out.segment(c * n, n).noalias() = j * (m * psi.segment((c + 1) * n, n));
    out.segment((c + 1) * n, n).noalias() = -j * (m * psi.segment(c * n, n));
  }
}

void EpmcProblem::evaluate(const VectorXd& u, double lambda, VectorXd& r, MatrixXd* jacobian, VectorXd* r_lambda) {
  const int N = hbm_.unknowns(), n = hbm_.retained_dofs();
  const VectorXd psi = u.head(N);
  const double omega = u(N), xi = u(N + 1), a = std::pow(10.0, lambda);
  const bool need_j = jacobian || r_lambda;
  hbm_.evaluate(a * psi, omega, r_hb_, need_j ? &j_hb_ : nullptr, jacobian ? &r_omega_ : nullptr);
  mass_derivative(psi, dpsi_);
  const double s = residual_scale_;  // the two normalisation rows weigh as the residual
  const int ia = first_cosine_ * n, ib = ia + n;
  const auto a1 = psi.segment(ia, n), b1 = psi.segment(ib, n);
  const MatrixXd& m = hbm_.model().mass;
  r.resize(N + 2);
  r.head(N) = r_hb_ / a - xi * omega * dpsi_;
  r(N) = s * (a1.dot(m * a1) + b1.dot(m * b1) - 1.0);
  r(N + 1) = s * mode_m_.dot(b1);
  if (jacobian) {
    MatrixXd& J = *jacobian;
    J.setZero(N + 2, N + 2);
    J.topLeftCorner(N, N) = j_hb_;  // d(R(a psi)/a)/d psi
    const FourierBasis& basis = hbm_.basis();
    for (int c = 0; c < basis.coefficients(); ++c) {
      const int j = basis.harmonic_of(c);
      if (j == 0 || basis.is_sine(c)) continue;
      J.block(c * n, (c + 1) * n, n, n) -= xi * omega * j * m;
      J.block((c + 1) * n, c * n, n, n) += xi * omega * j * m;
    }
    J.col(N).head(N) = r_omega_ / a - xi * dpsi_;
    J.col(N + 1).head(N) = -omega * dpsi_;
    J.row(N).segment(ia, n) = 2 * s * (m * a1).transpose();
    J.row(N).segment(ib, n) = 2 * s * (m * b1).transpose();
    J.row(N + 1).segment(ib, n) = s * mode_m_.transpose();
  }
  if (r_lambda) {
    // d/d(log10 a) of R(a psi)/a = ln 10 (J psi - R / a).
    r_lambda->setZero(N + 2);
    r_lambda->head(N) = std::numbers::ln10 * (j_hb_ * psi - r_hb_ / a);
  }
}

VectorXd EpmcProblem::unknown_scale(const VectorXd&) const {
  VectorXd scale = VectorXd::Constant(hbm_.unknowns() + 2, psi_scale_);
  scale(hbm_.unknowns()) = omega_scale_;
  scale(hbm_.unknowns() + 1) = xi_scale_;
  return scale;
}

BackbonePoint backbone_point(HarmonicBalance& hbm, const VectorXd& u, double lambda, const std::vector<OutputDof>& outputs) {
  const int N = hbm.unknowns();
  BackbonePoint p;
  p.amplitude = std::pow(10.0, lambda);
  p.omega = u(N);
  p.xi = u(N + 1);
  p.damping_ratio = p.xi / (2.0 * p.omega);
  const VectorXd x = p.amplitude * u.head(N);
  p.recorded = record_point(hbm, x, p.omega, outputs);
  const VectorXd full = hbm.expand(x, p.omega);
  const int h = hbm.basis().harmonics();
  const std::vector<int>& listed = hbm.basis().harmonic_numbers();
  for (const OutputDof& o : outputs) {
    const VectorXd c = dof_harmonics(full, hbm.model().dofs(), h, o.dof);
    VectorXd magnitudes(static_cast<Eigen::Index>(listed.size()));  // as branch.csv of frc: h0 the (signed) mean
    for (size_t i = 0; i < listed.size(); ++i) magnitudes(static_cast<Eigen::Index>(i)) = harmonic_magnitude(c, listed[i]);
    p.harmonics.push_back(magnitudes);
  }
  return p;
}

BackboneResult compute_backbone(const HarmonicBalance& hbm, const BackboneOptions& options, const std::vector<OutputDof>& outputs,
                                const BackboneObserver& observer) {
  options.validate();
  // The EPMC's negative damping is outside the harmonic balance: a DLFT contact would balance
  // the wrong linear residual.
  hbm.refuse_residual_elements("the backbone (EPMC)");
  const StructuralModel& model = hbm.model();
  if (hbm.retained_dofs() != model.dofs())
    throw std::invalid_argument("backbone: needs every dof as unknown (harmonic_balance.condensation = \"none\")");
  const NormalModes modes = normal_modes(model.mass, model.stiffness);
  if (options.mode > modes.frequencies.size())
    throw std::invalid_argument("mode: " + std::to_string(options.mode) + " is beyond the model's " +
                                std::to_string(modes.frequencies.size()) + " modes");
  const VectorXd phi = modes.shapes.col(options.mode - 1);
  BackboneResult result;
  result.linear_omega = modes.frequencies(options.mode - 1);
  if (!(result.linear_omega > 0)) throw std::invalid_argument("mode: " + std::to_string(options.mode) + " has no positive frequency");
  // The linear EPMC: (K - w^2 M) phi + i w (C - xi M) phi = 0 projected on phi gives xi = phi^T C phi.
  result.linear_xi = phi.dot(model.damping * phi);

  const int N = hbm.unknowns(), n = model.dofs();
  VectorXd u0 = VectorXd::Zero(N + 2);
  u0.segment(hbm.basis().cosine_index(1) * n, n) = phi;  // cosine part of harmonic 1: psi_1^T M psi_1 = 1
  u0(N) = result.linear_omega;
  u0(N + 1) = result.linear_xi;
  const double residual = (model.stiffness * phi).cwiseAbs().maxCoeff();
  // xi's unit: its linear value or a 1 % damping ratio (xi = 2 zeta omega), whichever is larger.
  const double xi_scale = std::max(std::abs(result.linear_xi), 0.02 * result.linear_omega);
  const double lambda0 = std::log10(options.amplitude_start), lambda1 = std::log10(options.amplitude_end);
  EpmcProblem problem(hbm, phi, phi.cwiseAbs().maxCoeff(), result.linear_omega, xi_scale, lambda1 - lambda0, residual > 0 ? residual : 1.0);
  const auto& co = options.continuation;
  if (newton_at_fixed_parameter(problem, u0, lambda0, co.tolerance, 4 * co.max_iterations) < 0)
    throw std::runtime_error("Newton did not converge on the mode at amplitude " + std::to_string(options.amplitude_start) +
                             " (start closer to the linear mode: a smaller LO)");
  const ParameterWindow window{lambda0, lambda1, 1, false};
  HarmonicBalance recorder = hbm.with_parameter(hbm.amplitude_parameter(), 0.0);  // unforced, as the problem
  result.continuation = continue_within(problem, u0, lambda0, window, co, [&](const BranchPoint& p, int index) {
    result.points.push_back(backbone_point(recorder, p.u, p.lambda, outputs));
    return !observer || observer(p, result.points.back(), index);
  });
  return result;
}

}  // namespace hbtrack
