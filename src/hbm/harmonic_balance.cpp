// The harmonic balance system's evaluations: residual, Jacobian and derivatives by the AFT,
// all const, reading the parameter values passed and writing into the caller's workspace.
#include "hbtrack/hbm/harmonic_balance_system.hpp"

#include <complex>
#include <optional>
#include <stdexcept>

#include "hbtrack/util/dense_product.hpp"
#include "hbtrack/util/phase_timer.hpp"

namespace hbtrack {

using cd = std::complex<double>;
using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Eigen::VectorXd;

void HarmonicBalanceSystem::sample(HarmonicBalanceWorkspace& ws, const VectorXd& x, double omega) const {
  const int q = retained_dofs();
  const Eigen::Map<const MatrixXd> coeffs(x.data(), q, basis_.coefficients());
  ws.coefficient_rows_ = coeffs.transpose();
  multiply(basis_.synthesis(), ws.coefficient_rows_, ws.x_samples_);
  multiply(basis_.derivative_synthesis(), ws.coefficient_rows_, ws.v_unit_samples_);
  for (size_t e = 0; e < elements_.size(); ++e) {
    const ElementSlot& s = slots_[e];
    ElementState& state = ws.elements_[e];
    for (size_t i = 0; i < s.columns.size(); ++i) {
      state.x.col(static_cast<Eigen::Index>(i)) = ws.x_samples_.col(s.columns[i]);
      state.v.col(static_cast<Eigen::Index>(i)) = fundamental(omega) * ws.v_unit_samples_.col(s.columns[i]);
    }
  }
}

VectorXcd HarmonicBalanceSystem::harmonic(const VectorXd& x, int slot, int dofs) const {
  const int c = slot_offset(slot);
  if (basis_.harmonic_of(c) == 0) return x.segment(0, dofs).cast<cd>();
  return x.segment(c * dofs, dofs).cast<cd>() - cd(0, 1) * x.segment((c + 1) * dofs, dofs).cast<cd>();
}

// The frequency an element is handed: the forcing's when it depends on it explicitly (the tip
// contact's rotation speed), else the basis' fundamental omega / nu, whose period the N samples
// span (a law averaged over each sample's interval, ScalarElement, reads the interval from it).
double element_frequency(const NonlinearElement& element, double omega, int subharmonic) {
  return element.depends_on_omega() ? omega : omega / subharmonic;
}

void HarmonicBalanceSystem::omega_derivative_samples(const HarmonicBalanceWorkspace& ws, size_t e, MatrixXd& df) const {
  // d f/d omega = (df/dv) v/omega + explicit dependence; v/omega = the unit-frequency velocity
  // over nu (v = (omega / nu) dx/dtau).
  const ElementSlot& s = slots_[e];
  const ElementResponse& resp = ws.elements_[e].response;
  const int k = static_cast<int>(s.columns.size());
  df.setZero(resp.force.rows(), k);
  if (resp.dforce_dv.size() > 0)
    for (int i = 0; i < k; ++i)
      for (int jd = 0; jd < k; ++jd)
        df.col(i).array() += resp.dforce_dv.col(i + k * jd).array() * ws.v_unit_samples_.col(s.columns[static_cast<size_t>(jd)]).array() /
                             options_.subharmonic;
  if (resp.dforce_domega.size() > 0) {
    // d/d(the frequency the element was handed): omega, or omega / nu (element_frequency).
    const NonlinearElement& element = *elements_[e];
    df += resp.dforce_domega * (element.depends_on_omega() ? 1.0 : 1.0 / options_.subharmonic);
  }
}

double HarmonicBalanceSystem::forcing_scale(const ParameterValues& p, double omega) const {
  return p[static_cast<size_t>(amplitude_index_)] * model_.forcing_growth.factor(omega);
}

void HarmonicBalanceSystem::add_condensed_linear_part(double amplitude, double omega, const CondensedOperators& at, const VectorXd& x,
                                                      VectorXd& r, MatrixXd* jacobian, VectorXd* r_omega) const {
  const int q = retained_dofs();
  // A growing forcing: its scale amplitude g(omega) in the residual, and -amplitude g'(omega) Fr
  // in R_omega beside the condenser's derivative at a fixed scale.
  const ForcingGrowth& growth = model_.forcing_growth;
  const double scale = amplitude * growth.factor(omega);
  const double scale_derivative = amplitude * growth.derivative(omega);
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const VectorXcd z = harmonic(x, slot, q);
    const Eigen::MatrixXcd& zr = at.reduced_stiffness[static_cast<size_t>(j)];
    const VectorXcd rc = zr * z - scale * at.reduced_force[static_cast<size_t>(j)];
    // z = a - i b and R_a - i R_b = rc, so R_a = Re(rc), R_b = -Im(rc).
    const int ia = slot_offset(slot) * q;
    r.segment(ia, q) += rc.real();
    if (j > 0) r.segment(ia + q, q) -= rc.imag();
    if (jacobian) {
      jacobian->block(ia, ia, q, q) += zr.real();
      if (j > 0) {
        const int ib = ia + q;
        jacobian->block(ia, ib, q, q) += zr.imag();
        jacobian->block(ib, ia, q, q) -= zr.imag();
        jacobian->block(ib, ib, q, q) += zr.real();
      }
    }
    if (r_omega) {  // the condenser's derivative is in the fundamental, omega / nu
      VectorXcd dc = condenser_->omega_derivative(j, z, scale, at) / static_cast<double>(options_.subharmonic);
      if (growth.active()) dc -= scale_derivative * at.reduced_force[static_cast<size_t>(j)];
      r_omega->segment(ia, q) += dc.real();
      if (j > 0) r_omega->segment(ia + q, q) -= dc.imag();
    }
  }
}

void HarmonicBalanceSystem::add_element_blocks(HarmonicBalanceWorkspace& ws, size_t e, double omega, int stride,
                                               const std::vector<int>& positions, MatrixXd* jacobian, MatrixXd* velocity_jacobian) const {
  // Block (i, j): Gamma^-1 diag(df_i/dx_j) Gamma + omega Gamma^-1 diag(df_i/dv_j) Gamma nabla,
  // built from the order-2H coefficients of the derivative signals (Toeplitz-plus-Hankel).
  // With velocity_jacobian, the velocity part Gamma^-1 diag(df_i/dv_j) Gamma goes there instead
  // (Hill's method keeps it apart). Row harmonic r of element forces is scaled by sigma_r.
  const ElementSlot& s = slots_[e];
  const ElementResponse& resp = ws.elements_[e].response;
  MatrixXd &block = ws.block_, &block_v = ws.block_v_, &coeffs = ws.coeffs_, &coeffs_v = ws.coeffs_v_;
  const int k = static_cast<int>(positions.size());
  const int nc = basis_.coefficients();
  auto scatter = [&](MatrixXd& target, const MatrixXd& part, int row_dof, int col_dof) {
    for (int cc = 0; cc < nc; ++cc)
      for (int rr = 0; rr < nc; ++rr) target(rr * stride + row_dof, cc * stride + col_dof) += s.sigma(rr) * part(rr, cc);
  };
  if (resp.history_operator) {
    // A history element whose sensitivities are an operator: S applied to the synthesis of
    // each dof's harmonics, then analysed. No velocity part.
    if (!jacobian) return;
    const int n = basis_.samples();
    for (int jd = 0; jd < k; ++jd) {
      Eigen::MatrixXd perturbation = MatrixXd::Zero(static_cast<Eigen::Index>(n) * k, nc);
      perturbation.middleRows(static_cast<Eigen::Index>(jd) * n, n) = basis_.synthesis();
      const MatrixXd response = resp.history_operator->apply(perturbation);
      for (int i = 0; i < k; ++i) {
        block.noalias() = basis_.analysis() * response.middleRows(static_cast<Eigen::Index>(i) * n, n);
        if (block.isZero(0.0)) continue;
        scatter(*jacobian, block, positions[static_cast<size_t>(i)], positions[static_cast<size_t>(jd)]);
      }
    }
    return;
  }
  if (resp.history_dforce_dx.size() > 0) {
    // A history element: block (i, j) = Gamma^-1 S_ij Gamma with S_ij the sparse N x N
    // sensitivities d f_i(t) / d x_j(s). No velocity part.
    if (!jacobian) return;
    const int n = basis_.samples();
    for (int jd = 0; jd < k; ++jd) {
      const MatrixXd sensitivity_times_basis = resp.history_dforce_dx.middleCols(jd * n, n) * basis_.synthesis();
      for (int i = 0; i < k; ++i) {
        block.noalias() = basis_.analysis() * sensitivity_times_basis.middleRows(i * n, n);
        if (block.isZero(0.0)) continue;
        scatter(*jacobian, block, positions[static_cast<size_t>(i)], positions[static_cast<size_t>(jd)]);
      }
    }
    return;
  }
  multiply(basis_.product_analysis(), resp.dforce_dx, coeffs);
  const bool with_v = resp.dforce_dv.size() > 0;
  if (with_v) multiply(basis_.product_analysis(), resp.dforce_dv, coeffs_v);
  block.resize(nc, nc);
  block_v.resize(nc, nc);
  for (int i = 0; i < k; ++i) {
    for (int jd = 0; jd < k; ++jd) {
      const int col = i + k * jd;
      const bool x_zero = coeffs.col(col).isZero(0.0);
      const bool v_zero = !with_v || coeffs_v.col(col).isZero(0.0);
      if (x_zero && v_zero) continue;
      const int ri = positions[static_cast<size_t>(i)], cj = positions[static_cast<size_t>(jd)];
      block.setZero();
      if (!x_zero) basis_.product_matrix(coeffs.col(col).data(), block);
      if (!v_zero) {
        basis_.product_matrix(coeffs_v.col(col).data(), block_v);
        if (velocity_jacobian) {
          scatter(*velocity_jacobian, block_v, ri, cj);
        } else {
          basis_.right_multiply_derivative(block_v);
          block += fundamental(omega) * block_v;
        }
      }
      if (jacobian) scatter(*jacobian, block, ri, cj);
    }
  }
}

void HarmonicBalanceSystem::evaluate(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x, double omega, VectorXd& r,
                                     MatrixXd* jacobian, VectorXd* r_omega) const {
  check(p, ws);
  const double amplitude = p[static_cast<size_t>(amplitude_index_)];
  const int q = retained_dofs();
  const int nc = basis_.coefficients();
  const int m = unknowns();
  if (x.size() != m) throw std::invalid_argument("HarmonicBalanceSystem::evaluate: x has the wrong size");
  {
    const ScopedPhase timing(Phase::jacobian);
    r.setZero(m);
    if (jacobian) jacobian->setZero(m, m);
    if (r_omega) r_omega->setZero(m);
  }
  {
    const ScopedPhase timing(Phase::aft);
    sample(ws, x, omega);
  }
  // With elements that read the linear residual, the linear part comes first and is kept apart.
  VectorXd r_linear, r_omega_linear;
  MatrixXd jacobian_linear;
  if (residual_elements_) {
    const ScopedPhase timing(Phase::jacobian);
    condenser_->update(omega, ws.condensed_);
    add_condensed_linear_part(amplitude, omega, ws.condensed_, x, r, jacobian, r_omega);
    r_linear = r;
    if (r_omega) r_omega_linear = *r_omega;
    if (jacobian) jacobian_linear = *jacobian;
  }
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    const ElementSlot& s = slots_[e];
    const int k = element.local_dofs();
    const ElementResponse& resp = ws.elements_[e].response;
    // The AFT: forces in time, their harmonics, and those of d f / d omega.
    std::optional<ScopedPhase> aft_timing(std::in_place, Phase::aft);
    evaluate_element(p, ws, e, omega, r_linear, false);

    multiply(basis_.analysis(), resp.force, ws.coeffs_);  // nc x k
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < nc; ++c) r(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * ws.coeffs_(c, i);

    if (r_omega) {
      omega_derivative_samples(ws, e, ws.omega_samples_);
      multiply(basis_.analysis(), ws.omega_samples_, ws.coeffs_);
      for (int i = 0; i < k; ++i)
        for (int c = 0; c < nc; ++c) (*r_omega)(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * ws.coeffs_(c, i);
      if (element.uses_linear_residual()) add_residual_response(ws, e, r_omega_linear, *r_omega);
    }
    aft_timing.reset();

    const ScopedPhase assembly_timing(Phase::jacobian);
    if (jacobian) add_element_blocks(ws, e, omega, q, s.columns, jacobian, nullptr);
    if (jacobian && element.uses_linear_residual()) add_residual_coupling(ws, e, jacobian_linear, *jacobian);
  }
  if (residual_elements_) return;
  // The condensed linear part (Schur complements per harmonic when omega changed).
  const ScopedPhase timing(Phase::jacobian);
  condenser_->update(fundamental(omega), ws.condensed_);
  add_condensed_linear_part(amplitude, omega, ws.condensed_, x, r, jacobian, r_omega);
}

VectorXd HarmonicBalanceSystem::parameter_derivative(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x,
                                                     double omega, int parameter) const {
  check(p, ws);
  const int q = retained_dofs();
  const int nc = basis_.coefficients();
  VectorXd out = VectorXd::Zero(unknowns());
  if (parameter < 0 || parameter >= parameters_.size()) throw std::out_of_range("parameter index out of range");
  if (parameter == amplitude_index_) {
    condenser_->update(fundamental(omega), ws.condensed_);
    for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
      const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
      // d/d(amplitude) of -amplitude g(omega) Fr
      const VectorXcd f = model_.forcing_growth.factor(omega) * ws.condensed_.reduced_force[static_cast<size_t>(j)];
      const int ia = slot_offset(slot) * q;
      out.segment(ia, q) -= f.real();
      if (j > 0) out.segment(ia + q, q) += f.imag();
    }
  }
  bool sampled = false;
  VectorXd r_linear;
  if (residual_elements_) {
    // The linear residual, and the amplitude's effect on it as the elements that read it see it.
    r_linear = linear_residual(p, ws, x, omega);
    sample(ws, x, omega);
    sampled = true;
    const VectorXd amplitude_part = out;
    for (size_t e = 0; e < elements_.size() && parameter == amplitude_index_; ++e) {
      if (!elements_[e]->uses_linear_residual()) continue;
      evaluate_element(p, ws, e, omega, r_linear, false);
      add_residual_response(ws, e, amplitude_part, out);
    }
  }
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    bool bound = false;
    for (const auto& b : element.properties) bound = bound || b.parameter == parameter;
    if (!bound) continue;
    const ScopedPhase timing(Phase::aft);
    if (!sampled) sample(ws, x, omega);
    sampled = true;
    const ElementSlot& s = slots_[e];
    const ElementState& state = ws.elements_[e];
    const int k = element.local_dofs();
    evaluate_element(p, ws, e, omega, r_linear, true);
    MatrixXd df = MatrixXd::Zero(state.x.rows(), k);
    for (size_t property = 0; property < element.properties.size(); ++property) {
      const double scale = element.properties[property].derivative(parameter);
      if (scale != 0.0) df += scale * state.response.dforce_dproperty.middleCols(static_cast<Eigen::Index>(k * property), k);
    }
    const MatrixXd coeffs = basis_.analysis() * df;
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < nc; ++c) out(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coeffs(c, i);
  }
  return out;
}

VectorXd HarmonicBalanceSystem::expand(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x, double omega) const {
  check(p, ws);
  const int q = retained_dofs();
  const int n = model_.dofs();
  const double amplitude = forcing_scale(p, omega);
  condenser_->update(fundamental(omega), ws.condensed_);
  VectorXd full = VectorXd::Zero(n * (2 * options_.harmonics + 1));
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const VectorXcd xf = condenser_->recover(j, harmonic(x, slot, q), amplitude, ws.condensed_);
    if (j == 0) {
      full.segment(0, n) = xf.real();
    } else {
      full.segment((2 * j - 1) * n, n) = xf.real();
      full.segment(2 * j * n, n) = -xf.imag();
    }
  }
  return full;
}

VectorXd HarmonicBalanceSystem::linear_solution(const ParameterValues& p, HarmonicBalanceWorkspace& ws, double omega) const {
  check(p, ws);
  const int q = retained_dofs();
  const double amplitude = forcing_scale(p, omega);
  const CondensedOperators& at = ws.condensed_;
  condenser_->update(fundamental(omega), ws.condensed_);
  VectorXd x(unknowns());
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const size_t h = static_cast<size_t>(j);
    const VectorXcd z = at.reduced_stiffness[h].partialPivLu().solve(amplitude * at.reduced_force[h]);
    const int ia = slot_offset(slot) * q;
    x.segment(ia, q) = z.real();
    if (j > 0) x.segment(ia + q, q) = -z.imag();
  }
  return x;
}

VectorXd HarmonicBalanceSystem::rest_linearized_solution(const ParameterValues& p, HarmonicBalanceWorkspace& ws, double omega) const {
  const VectorXd rest = VectorXd::Zero(unknowns());
  VectorXd r;
  MatrixXd jacobian;
  evaluate(p, ws, rest, omega, r, &jacobian, nullptr);
  return -jacobian.partialPivLu().solve(r);
}

VectorXd HarmonicBalanceSystem::nonlinear_forces(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x,
                                                 double omega) const {
  check(p, ws);
  VectorXd r = VectorXd::Zero(unknowns());
  const int q = retained_dofs();
  const VectorXd r_linear = residual_elements_ ? linear_residual(p, ws, x, omega) : VectorXd();
  sample(ws, x, omega);
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    const ElementSlot& s = slots_[e];
    evaluate_element(p, ws, e, omega, r_linear, false);
    const MatrixXd coeffs = basis_.analysis() * ws.elements_[e].response.force;
    for (int i = 0; i < element.local_dofs(); ++i)
      for (int c = 0; c < basis_.coefficients(); ++c) r(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coeffs(c, i);
  }
  return r;
}

double HarmonicBalanceSystem::nonlinear_adjoint_products(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x,
                                                         double omega, const VectorXd& w, VectorXd& jacobian_transpose_w) const {
  check(p, ws);
  const int q = retained_dofs();
  const int nc = basis_.coefficients();
  if (x.size() != unknowns() || w.size() != unknowns())
    throw std::invalid_argument("HarmonicBalanceSystem::nonlinear_adjoint_products: x or w has the wrong size");
  refuse_residual_elements("limit-point tracking");
  const ScopedPhase timing(Phase::aft);
  sample(ws, x, omega);
  MatrixXd &adjoint_x = ws.adjoint_x_, &adjoint_v = ws.adjoint_v_, &adjoint_local = ws.adjoint_local_, &coeffs = ws.coeffs_;
  // Block (i, j) of J_nl is diag(sigma) Gamma^-1 [diag(df_i/dx_j) Gamma + omega diag(df_i/dv_j) Gamma nabla]
  // (add_element_blocks; product_matrix equals Gamma^-1 diag(g) Gamma for any N). Its transpose
  // takes w_i to samples by (diag(sigma) Gamma^-1)^T, weighs them by the derivative signals and
  // returns to coefficients by Gamma^T and (Gamma nabla)^T. The same samples of w give
  // w . diag(sigma) Gamma^-1 df/d(omega) as a dot product in time.
  adjoint_x.setZero(basis_.samples(), q);
  adjoint_v.setZero(basis_.samples(), q);
  double w_dot_omega_derivative = 0.0;
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    const ElementSlot& s = slots_[e];
    ElementState& state = ws.elements_[e];
    const int k = element.local_dofs();
    element.evaluate(state.x, state.v, element_frequency(element, omega, options_.subharmonic), element.property_values(p), state.response,
                     false);
    const ElementResponse& resp = state.response;
    coeffs.resize(nc, k);
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < nc; ++c) coeffs(c, i) = s.sigma(c) * w(c * q + s.columns[static_cast<size_t>(i)]);
    adjoint_local.noalias() = basis_.analysis().transpose() * coeffs;
    omega_derivative_samples(ws, e, ws.omega_samples_);
    w_dot_omega_derivative += (adjoint_local.array() * ws.omega_samples_.array()).sum();
    const bool with_v = resp.dforce_dv.size() > 0;
    if (resp.history_dforce_dx.size() > 0 || resp.history_operator) {
      // History element: the transposed sensitivities map the weights back to earlier samples.
      const Eigen::Map<const VectorXd> local(adjoint_local.data(), adjoint_local.size());
      const VectorXd back = resp.history_operator ? VectorXd(resp.history_operator->apply_transpose(local))
                                                  : VectorXd(resp.history_dforce_dx.transpose() * local);
      const Eigen::Index n = basis_.samples();
      for (int jd = 0; jd < k; ++jd) adjoint_x.col(s.columns[static_cast<size_t>(jd)]) += back.segment(jd * n, n);
      continue;
    }
    for (int jd = 0; jd < k; ++jd) {
      const int column = s.columns[static_cast<size_t>(jd)];
      for (int i = 0; i < k; ++i) {
        adjoint_x.col(column).array() += resp.dforce_dx.col(i + k * jd).array() * adjoint_local.col(i).array();
        if (with_v) adjoint_v.col(column).array() += resp.dforce_dv.col(i + k * jd).array() * adjoint_local.col(i).array();
      }
    }
  }
  jacobian_transpose_w.resize(unknowns());
  Eigen::Map<MatrixXd> out_coeffs(jacobian_transpose_w.data(), q, nc);
  out_coeffs.noalias() = adjoint_x.transpose() * basis_.synthesis();
  out_coeffs.noalias() += fundamental(omega) * (adjoint_v.transpose() * basis_.derivative_synthesis());
  return w_dot_omega_derivative;
}

VectorXd HarmonicBalanceSystem::linear_omega_derivative(HarmonicBalanceWorkspace& ws, const VectorXd& d, double omega) const {
  const int q = retained_dofs();
  if (d.size() != unknowns()) throw std::invalid_argument("HarmonicBalanceSystem::linear_omega_derivative: d has the wrong size");
  const ScopedPhase timing(Phase::jacobian);
  condenser_->update(fundamental(omega), ws.condensed_);
  VectorXd out = VectorXd::Zero(unknowns());
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    // Amplitude 0: without the forcing term, omega_derivative is linear in z.
    const VectorXcd dc =
        condenser_->omega_derivative(j, harmonic(d, slot, q), 0.0, ws.condensed_) / static_cast<double>(options_.subharmonic);
    const int ia = slot_offset(slot) * q;
    out.segment(ia, q) += dc.real();
    if (j > 0) out.segment(ia + q, q) -= dc.imag();
  }
  return out;
}

}  // namespace hbtrack
