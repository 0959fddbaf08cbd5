#include "hbtrack/hbm/harmonic_balance.hpp"

#include <algorithm>
#include <cstdio>
#include <complex>
#include <optional>
#include <set>
#include <stdexcept>

#include "hbtrack/elements/lanczos.hpp"
#include "hbtrack/util/dense_product.hpp"
#include "hbtrack/util/phase_timer.hpp"

namespace hbtrack {

using cd = std::complex<double>;
using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Eigen::VectorXd;

namespace {
std::string list_text(const std::vector<int>& list) {
  std::string text = "[";
  for (size_t i = 0; i < list.size(); ++i) text += (i ? ", " : "") + std::to_string(list[i]);
  return text + "]";
}
}  // namespace

std::vector<int> HarmonicBalanceOptions::selected_harmonics() const {
  if (!harmonic_list.empty()) return harmonic_list;
  std::vector<int> all;
  for (int k = 0; k <= harmonics; ++k) all.push_back(k);
  return all;
}

void HarmonicBalanceOptions::select(const std::vector<int>& list) {
  bool full = !list.empty() && list.front() == 0;
  for (size_t i = 0; full && i < list.size(); ++i) full = list[i] == static_cast<int>(i);
  harmonic_list = full ? std::vector<int>{} : list;
  if (!list.empty()) harmonics = list.back();
}

std::string harmonic_label(int k, int subharmonic) {
  if (subharmonic <= 1 || k % subharmonic == 0) return std::to_string(subharmonic <= 1 ? k : k / subharmonic);
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", static_cast<double>(k) / subharmonic);
  return text;
}

void HarmonicBalanceOptions::validate() const {
  if (!harmonic_list.empty()) {
    const std::string got = ", got " + list_text(harmonic_list);
    for (size_t i = 0; i < harmonic_list.size(); ++i) {
      if (harmonic_list[i] < 0) throw std::invalid_argument("harmonic_balance.harmonics: a list of harmonics must hold integers >= 0" + got);
      if (i > 0 && harmonic_list[i] <= harmonic_list[i - 1])
        throw std::invalid_argument("harmonic_balance.harmonics: a list of harmonics must be sorted and unique (increasing)" + got);
    }
    if (harmonic_list.back() < 1) throw std::invalid_argument("harmonic_balance.harmonics: a list of harmonics needs one >= 1" + got);
    if (harmonics != harmonic_list.back())
      throw std::invalid_argument("harmonic_balance.harmonics: H = " + std::to_string(harmonics) + " is not the list's largest" + got);
  }
  if (subharmonic < 1 || subharmonic > 16)
    throw std::invalid_argument("harmonic_balance.subharmonic: must be in [1, 16], got " + std::to_string(subharmonic));
  if (harmonics < 1) throw std::invalid_argument("harmonic_balance.harmonics: must be >= 1, got " + std::to_string(harmonics));
  if (harmonics > 500) throw std::invalid_argument("harmonic_balance.harmonics: must be <= 500, got " + std::to_string(harmonics));
  if (samples != 0 && samples < 2 * harmonics + 1)
    throw std::invalid_argument("harmonic_balance.samples: must be >= 2*harmonics+1 = " + std::to_string(2 * harmonics + 1) +
                                ", got " + std::to_string(samples));
  if (samples > (1 << 20)) throw std::invalid_argument("harmonic_balance.samples: must be <= 1048576");
}

int HarmonicBalanceOptions::effective_samples() const {
  if (samples > 0) return samples;
  int n = 16;
  while (n < 8 * (harmonics + 1)) n *= 2;
  return n;
}

HarmonicBalance::HarmonicBalance(StructuralModel model, ElementList elements, ParameterSet parameters,
                                 HarmonicBalanceOptions options)
    : model_(std::move(model)),
      elements_(std::move(elements)),
      parameters_(std::move(parameters)),
      options_(std::move(options)),
      basis_((options_.validate(), options_.selected_harmonics()), options_.effective_samples()) {
  model_.validate();
  const std::vector<int>& listed = basis_.harmonic_numbers();
  for (const HarmonicForce& h : model_.forcing)
    if (std::find(listed.begin(), listed.end(), h.order * options_.subharmonic) == listed.end())
      throw std::invalid_argument("forcing harmonic " + std::to_string(h.order) + " is not among the harmonics balanced, " +
                                  list_text(listed) + (options_.subharmonic > 1 ? " x omega/" + std::to_string(options_.subharmonic) : "") +
                                  " (it would be dropped)");
  for (int c = 0; c < basis_.coefficients(); ++c)
    if (c == 0 || basis_.harmonic_of(c) != basis_.harmonic_of(c - 1)) slot_offset_.push_back(c);
  // The condensers' harmonic j is at j * fundamental: the forcing's order h is harmonic h nu.
  StructuralModel linear_model = model_;
  for (HarmonicForce& h : linear_model.forcing) h.order *= options_.subharmonic;
  amplitude_index_ = parameters_.find("amplitude");
  if (amplitude_index_ < 0) amplitude_index_ = parameters_.set("amplitude", 1.0);

  std::set<int> nonlinear;
  for (const auto& e : elements_) {
    if (static_cast<int>(e->properties.size()) != static_cast<int>(e->property_names().size()))
      throw std::invalid_argument("element " + e->type() + ": property count does not match");
    for (int d : e->dofs) {
      if (d < 0 || d >= model_.dofs()) throw std::invalid_argument("element " + e->type() + ": dof index out of range");
      nonlinear.insert(d);
    }
  }
  Condensation method = options_.condensation;
  if (nonlinear.empty()) method = Condensation::none;  // a linear model: keep every dof as unknown
  if (method == Condensation::none) {
    for (int i = 0; i < model_.dofs(); ++i) retained_.push_back(i);
  } else {
    retained_.assign(nonlinear.begin(), nonlinear.end());
  }
  // Modal condensation inverts the retained dofs' receptance, a sum over every mode: with many
  // retained dofs (the blade's 27 tip dofs of 39) it is ill-conditioned (1e7 near a resonance)
  // and Newton stalls, while the Schur complement of a small linear block is cheap anyway. So
  // `auto` takes modal only when the retained dofs are a small part of the model.
  if (method == Condensation::automatic) {
    const bool few_retained = 4 * retained_.size() <= static_cast<size_t>(model_.dofs());
    method = few_retained && modes_diagonalise_damping(model_) ? Condensation::modal : Condensation::schur;
  }
  if (method == Condensation::modal) {
    if (!modes_diagonalise_damping(model_))
      throw std::invalid_argument("harmonic_balance.condensation: 'modal' needs damping diagonalised by the normal modes and K > 0; use 'schur'");
    condenser_ = make_modal_condenser(linear_model, retained_, options_.harmonics);
  } else {
    condenser_ = make_schur_condenser(linear_model, retained_, options_.harmonics);
  }

  // An element that reads the linear residual at its dofs (DLFT) must be alone on them: another
  // element's force there would be part of what the contact balances.
  for (size_t e = 0; e < elements_.size(); ++e) {
    if (!elements_[e]->uses_linear_residual()) continue;
    residual_elements_ = true;
    if (elements_[e]->lanczos_exponent != 0.0)
      throw std::invalid_argument("element " + elements_[e]->type() + " reads the linear residual (DLFT): no Lanczos filter on it");
    for (size_t o = 0; o < elements_.size(); ++o)
      for (int d : elements_[o]->dofs)
        if (o != e && std::find(elements_[e]->dofs.begin(), elements_[e]->dofs.end(), d) != elements_[e]->dofs.end())
          throw std::invalid_argument("element " + elements_[e]->type() + " reads the linear residual (DLFT) at dof " + model_.dof_names[static_cast<size_t>(d)] +
                                      ", which another element (" + elements_[o]->type() + ") also acts on");
  }
  const int n_samples = basis_.samples();
  slots_.resize(elements_.size());
  for (size_t e = 0; e < elements_.size(); ++e) {
    ElementSlot& s = slots_[e];
    for (int d : elements_[e]->dofs)
      s.columns.push_back(static_cast<int>(std::lower_bound(retained_.begin(), retained_.end(), d) - retained_.begin()));
    const Eigen::VectorXd dense_sigma = lanczos_factors(options_.harmonics, elements_[e]->lanczos_exponent);
    s.sigma.resize(basis_.coefficients());
    for (int c = 0; c < basis_.coefficients(); ++c) s.sigma(c) = dense_sigma(basis_.dense_index(c));
    s.x.resize(n_samples, elements_[e]->local_dofs());
    s.v.resize(n_samples, elements_[e]->local_dofs());
  }
}

void HarmonicBalance::sample(const VectorXd& x, double omega) {
  const int q = retained_dofs();
  const Eigen::Map<const MatrixXd> coeffs(x.data(), q, basis_.coefficients());
  coefficient_rows_ = coeffs.transpose();
  multiply(basis_.synthesis(), coefficient_rows_, x_samples_);
  multiply(basis_.derivative_synthesis(), coefficient_rows_, v_unit_samples_);
  for (size_t e = 0; e < elements_.size(); ++e) {
    ElementSlot& s = slots_[e];
    for (size_t i = 0; i < s.columns.size(); ++i) {
      s.x.col(static_cast<Eigen::Index>(i)) = x_samples_.col(s.columns[i]);
      s.v.col(static_cast<Eigen::Index>(i)) = fundamental(omega) * v_unit_samples_.col(s.columns[i]);
    }
  }
}

VectorXcd HarmonicBalance::harmonic(const VectorXd& x, int slot, int dofs) const {
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

void HarmonicBalance::omega_derivative_samples(const ElementSlot& s, MatrixXd& df) const {
  // d f/d omega = (df/dv) v/omega + explicit dependence; v/omega = the unit-frequency velocity
  // over nu (v = (omega / nu) dx/dtau).
  const ElementResponse& resp = s.response;
  const int k = static_cast<int>(s.columns.size());
  df.setZero(resp.force.rows(), k);
  if (resp.dforce_dv.size() > 0)
    for (int i = 0; i < k; ++i)
      for (int jd = 0; jd < k; ++jd)
        df.col(i).array() += resp.dforce_dv.col(i + k * jd).array() * v_unit_samples_.col(s.columns[static_cast<size_t>(jd)]).array() /
                             options_.subharmonic;
  if (resp.dforce_domega.size() > 0) {
    // d/d(the frequency the element was handed): omega, or omega / nu (element_frequency).
    const NonlinearElement& element = *elements_[static_cast<size_t>(&s - slots_.data())];
    df += resp.dforce_domega * (element.depends_on_omega() ? 1.0 : 1.0 / options_.subharmonic);
  }
}

void HarmonicBalance::add_condensed_linear_part(const VectorXd& x, VectorXd& r, MatrixXd* jacobian, VectorXd* r_omega) {
  const int q = retained_dofs();
  const double amplitude = parameters_.value(amplitude_index_);
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const VectorXcd z = harmonic(x, slot, q);
    const Eigen::MatrixXcd& zr = condenser_->reduced_stiffness(j);
    const VectorXcd rc = zr * z - amplitude * condenser_->reduced_force(j);
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
      const VectorXcd dc = condenser_->omega_derivative(j, z, amplitude) / static_cast<double>(options_.subharmonic);
      r_omega->segment(ia, q) += dc.real();
      if (j > 0) r_omega->segment(ia + q, q) -= dc.imag();
    }
  }
}

void HarmonicBalance::add_element_blocks(ElementSlot& s, double omega, int stride, const std::vector<int>& positions,
                                          MatrixXd* jacobian, MatrixXd* velocity_jacobian) {
  // Block (i, j): Gamma^-1 diag(df_i/dx_j) Gamma + omega Gamma^-1 diag(df_i/dv_j) Gamma nabla,
  // built from the order-2H coefficients of the derivative signals (Toeplitz-plus-Hankel).
  // With velocity_jacobian, the velocity part Gamma^-1 diag(df_i/dv_j) Gamma goes there instead
  // (Hill's method keeps it apart). Row harmonic r of element forces is scaled by sigma_r.
  const ElementResponse& resp = s.response;
  const int k = static_cast<int>(positions.size());
  const int nc = basis_.coefficients();
  auto scatter = [&](MatrixXd& target, const MatrixXd& block, int row_dof, int col_dof) {
    for (int cc = 0; cc < nc; ++cc)
      for (int rr = 0; rr < nc; ++rr) target(rr * stride + row_dof, cc * stride + col_dof) += s.sigma(rr) * block(rr, cc);
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
        block_.noalias() = basis_.analysis() * response.middleRows(static_cast<Eigen::Index>(i) * n, n);
        if (block_.isZero(0.0)) continue;
        scatter(*jacobian, block_, positions[static_cast<size_t>(i)], positions[static_cast<size_t>(jd)]);
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
        block_.noalias() = basis_.analysis() * sensitivity_times_basis.middleRows(i * n, n);
        if (block_.isZero(0.0)) continue;
        scatter(*jacobian, block_, positions[static_cast<size_t>(i)], positions[static_cast<size_t>(jd)]);
      }
    }
    return;
  }
  multiply(basis_.product_analysis(), resp.dforce_dx, coeffs_);
  const bool with_v = resp.dforce_dv.size() > 0;
  if (with_v) multiply(basis_.product_analysis(), resp.dforce_dv, coeffs_v_);
  block_.resize(nc, nc);
  block_v_.resize(nc, nc);
  for (int i = 0; i < k; ++i) {
    for (int jd = 0; jd < k; ++jd) {
      const int col = i + k * jd;
      const bool x_zero = coeffs_.col(col).isZero(0.0);
      const bool v_zero = !with_v || coeffs_v_.col(col).isZero(0.0);
      if (x_zero && v_zero) continue;
      const int ri = positions[static_cast<size_t>(i)], cj = positions[static_cast<size_t>(jd)];
      block_.setZero();
      if (!x_zero) basis_.product_matrix(coeffs_.col(col).data(), block_);
      if (!v_zero) {
        basis_.product_matrix(coeffs_v_.col(col).data(), block_v_);
        if (velocity_jacobian) {
          scatter(*velocity_jacobian, block_v_, ri, cj);
        } else {
          basis_.right_multiply_derivative(block_v_);
          block_ += fundamental(omega) * block_v_;
        }
      }
      if (jacobian) scatter(*jacobian, block_, ri, cj);
    }
  }
}

void HarmonicBalance::evaluate(const VectorXd& x, double omega, VectorXd& r, MatrixXd* jacobian, VectorXd* r_omega) {
  const int q = retained_dofs();
  const int nc = basis_.coefficients();
  const int m = unknowns();
  if (x.size() != m) throw std::invalid_argument("HarmonicBalance::evaluate: x has the wrong size");
  {
    const ScopedPhase timing(Phase::jacobian);
    r.setZero(m);
    if (jacobian) jacobian->setZero(m, m);
    if (r_omega) r_omega->setZero(m);
  }
  {
    const ScopedPhase timing(Phase::aft);
    sample(x, omega);
  }
  // With elements that read the linear residual, the linear part comes first and is kept apart.
  VectorXd r_linear, r_omega_linear;
  MatrixXd jacobian_linear;
  if (residual_elements_) {
    const ScopedPhase timing(Phase::jacobian);
    condenser_->update(omega);
    add_condensed_linear_part(x, r, jacobian, r_omega);
    r_linear = r;
    if (r_omega) r_omega_linear = *r_omega;
    if (jacobian) jacobian_linear = *jacobian;
  }
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    ElementSlot& s = slots_[e];
    const int k = element.local_dofs();
    const ElementResponse& resp = s.response;
    // The AFT: forces in time, their harmonics, and those of d f / d omega.
    std::optional<ScopedPhase> aft_timing(std::in_place, Phase::aft);
    evaluate_element(e, omega, r_linear, false);

    multiply(basis_.analysis(), resp.force, coeffs_);  // nc x k
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < nc; ++c) r(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coeffs_(c, i);

    if (r_omega) {
      omega_derivative_samples(s, omega_samples_);
      multiply(basis_.analysis(), omega_samples_, coeffs_);
      for (int i = 0; i < k; ++i)
        for (int c = 0; c < nc; ++c) (*r_omega)(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coeffs_(c, i);
      if (element.uses_linear_residual()) add_residual_response(s, r_omega_linear, *r_omega);
    }
    aft_timing.reset();

    const ScopedPhase assembly_timing(Phase::jacobian);
    if (jacobian) add_element_blocks(s, omega, q, s.columns, jacobian, nullptr);
    if (jacobian && element.uses_linear_residual()) add_residual_coupling(s, jacobian_linear, *jacobian);
  }
  if (residual_elements_) return;
  // The condensed linear part (Schur complements per harmonic when omega changed).
  const ScopedPhase timing(Phase::jacobian);
  condenser_->update(fundamental(omega));
  add_condensed_linear_part(x, r, jacobian, r_omega);
}

VectorXd HarmonicBalance::parameter_derivative(const VectorXd& x, double omega, int parameter) {
  const int q = retained_dofs();
  const int nc = basis_.coefficients();
  VectorXd out = VectorXd::Zero(unknowns());
  if (parameter < 0 || parameter >= parameters_.size()) throw std::out_of_range("parameter index out of range");
  if (parameter == amplitude_index_) {
    condenser_->update(fundamental(omega));
    for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
      const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
      const VectorXcd& f = condenser_->reduced_force(j);
      const int ia = slot_offset(slot) * q;
      out.segment(ia, q) -= f.real();
      if (j > 0) out.segment(ia + q, q) += f.imag();
    }
  }
  bool sampled = false;
  VectorXd r_linear;
  if (residual_elements_) {
    // The linear residual, and the amplitude's effect on it as the elements that read it see it.
    r_linear = linear_residual(x, omega);
    sample(x, omega);
    sampled = true;
    const VectorXd amplitude_part = out;
    for (size_t e = 0; e < elements_.size() && parameter == amplitude_index_; ++e) {
      if (!elements_[e]->uses_linear_residual()) continue;
      evaluate_element(e, omega, r_linear, false);
      add_residual_response(slots_[e], amplitude_part, out);
    }
  }
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    bool bound = false;
    for (const auto& b : element.properties) bound = bound || b.parameter == parameter;
    if (!bound) continue;
    const ScopedPhase timing(Phase::aft);
    if (!sampled) sample(x, omega);
    sampled = true;
    ElementSlot& s = slots_[e];
    const int k = element.local_dofs();
    evaluate_element(e, omega, r_linear, true);
    MatrixXd df = MatrixXd::Zero(s.x.rows(), k);
    for (size_t p = 0; p < element.properties.size(); ++p) {
      const double scale = element.properties[p].derivative(parameter);
      if (scale != 0.0) df += scale * s.response.dforce_dproperty.middleCols(static_cast<Eigen::Index>(k * p), k);
    }
    const MatrixXd coeffs = basis_.analysis() * df;
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < nc; ++c) out(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coeffs(c, i);
  }
  return out;
}

VectorXd HarmonicBalance::expand(const VectorXd& x, double omega) {
  const int q = retained_dofs();
  const int n = model_.dofs();
  const double amplitude = parameters_.value(amplitude_index_);
  condenser_->update(fundamental(omega));
  VectorXd full = VectorXd::Zero(n * (2 * options_.harmonics + 1));
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const VectorXcd xf = condenser_->recover(j, harmonic(x, slot, q), amplitude);
    if (j == 0) {
      full.segment(0, n) = xf.real();
    } else {
      full.segment((2 * j - 1) * n, n) = xf.real();
      full.segment(2 * j * n, n) = -xf.imag();
    }
  }
  return full;
}

VectorXd HarmonicBalance::linear_solution(double omega) {
  const int q = retained_dofs();
  const double amplitude = parameters_.value(amplitude_index_);
  condenser_->update(fundamental(omega));
  VectorXd x(unknowns());
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    const VectorXcd z = condenser_->reduced_stiffness(j).partialPivLu().solve(amplitude * condenser_->reduced_force(j));
    const int ia = slot_offset(slot) * q;
    x.segment(ia, q) = z.real();
    if (j > 0) x.segment(ia + q, q) = -z.imag();
  }
  return x;
}

VectorXd HarmonicBalance::rest_linearized_solution(double omega) {
  const VectorXd rest = VectorXd::Zero(unknowns());
  VectorXd r;
  MatrixXd jacobian;
  evaluate(rest, omega, r, &jacobian, nullptr);
  return -jacobian.partialPivLu().solve(r);
}

VectorXd HarmonicBalance::nonlinear_forces(const VectorXd& x, double omega) {
  VectorXd r = VectorXd::Zero(unknowns());
  const int q = retained_dofs();
  const VectorXd r_linear = residual_elements_ ? linear_residual(x, omega) : VectorXd();
  sample(x, omega);
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    ElementSlot& s = slots_[e];
    evaluate_element(e, omega, r_linear, false);
    const MatrixXd coeffs = basis_.analysis() * s.response.force;
    for (int i = 0; i < element.local_dofs(); ++i)
      for (int c = 0; c < basis_.coefficients(); ++c) r(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coeffs(c, i);
  }
  return r;
}

double HarmonicBalance::nonlinear_adjoint_products(const VectorXd& x, double omega, const VectorXd& w,
                                                   VectorXd& jacobian_transpose_w) {
  const int q = retained_dofs();
  const int nc = basis_.coefficients();
  if (x.size() != unknowns() || w.size() != unknowns())
    throw std::invalid_argument("HarmonicBalance::nonlinear_adjoint_products: x or w has the wrong size");
  refuse_residual_elements("limit-point tracking");
  const ScopedPhase timing(Phase::aft);
  sample(x, omega);
  // Block (i, j) of J_nl is diag(sigma) Gamma^-1 [diag(df_i/dx_j) Gamma + omega diag(df_i/dv_j) Gamma nabla]
  // (add_element_blocks; product_matrix equals Gamma^-1 diag(g) Gamma for any N). Its transpose
  // takes w_i to samples by (diag(sigma) Gamma^-1)^T, weighs them by the derivative signals and
  // returns to coefficients by Gamma^T and (Gamma nabla)^T. The same samples of w give
  // w . diag(sigma) Gamma^-1 df/d(omega) as a dot product in time.
  adjoint_x_.setZero(basis_.samples(), q);
  adjoint_v_.setZero(basis_.samples(), q);
  double w_dot_omega_derivative = 0.0;
  for (size_t e = 0; e < elements_.size(); ++e) {
    const NonlinearElement& element = *elements_[e];
    ElementSlot& s = slots_[e];
    const int k = element.local_dofs();
    element.evaluate(s.x, s.v, element_frequency(element, omega, options_.subharmonic), element.property_values(parameters_), s.response, false);
    const ElementResponse& resp = s.response;
    coeffs_.resize(nc, k);
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < nc; ++c) coeffs_(c, i) = s.sigma(c) * w(c * q + s.columns[static_cast<size_t>(i)]);
    adjoint_local_.noalias() = basis_.analysis().transpose() * coeffs_;
    omega_derivative_samples(s, omega_samples_);
    w_dot_omega_derivative += (adjoint_local_.array() * omega_samples_.array()).sum();
    const bool with_v = resp.dforce_dv.size() > 0;
    if (resp.history_dforce_dx.size() > 0 || resp.history_operator) {
      // History element: the transposed sensitivities map the weights back to earlier samples.
      const Eigen::Map<const VectorXd> local(adjoint_local_.data(), adjoint_local_.size());
      const VectorXd back = resp.history_operator ? VectorXd(resp.history_operator->apply_transpose(local))
                                                  : VectorXd(resp.history_dforce_dx.transpose() * local);
      const Eigen::Index n = basis_.samples();
      for (int jd = 0; jd < k; ++jd) adjoint_x_.col(s.columns[static_cast<size_t>(jd)]) += back.segment(jd * n, n);
      continue;
    }
    for (int jd = 0; jd < k; ++jd) {
      const int column = s.columns[static_cast<size_t>(jd)];
      for (int i = 0; i < k; ++i) {
        adjoint_x_.col(column).array() += resp.dforce_dx.col(i + k * jd).array() * adjoint_local_.col(i).array();
        if (with_v) adjoint_v_.col(column).array() += resp.dforce_dv.col(i + k * jd).array() * adjoint_local_.col(i).array();
      }
    }
  }
  jacobian_transpose_w.resize(unknowns());
  Eigen::Map<MatrixXd> out_coeffs(jacobian_transpose_w.data(), q, nc);
  out_coeffs.noalias() = adjoint_x_.transpose() * basis_.synthesis();
  out_coeffs.noalias() += fundamental(omega) * (adjoint_v_.transpose() * basis_.derivative_synthesis());
  return w_dot_omega_derivative;
}

VectorXd HarmonicBalance::linear_omega_derivative(const VectorXd& d, double omega) {
  const int q = retained_dofs();
  if (d.size() != unknowns()) throw std::invalid_argument("HarmonicBalance::linear_omega_derivative: d has the wrong size");
  const ScopedPhase timing(Phase::jacobian);
  condenser_->update(fundamental(omega));
  VectorXd out = VectorXd::Zero(unknowns());
  for (int slot = 0; slot < static_cast<int>(slot_offset_.size()); ++slot) {
    const int j = basis_.harmonic_numbers()[static_cast<size_t>(slot)];
    // Amplitude 0: without the forcing term, omega_derivative is linear in z.
    const VectorXcd dc = condenser_->omega_derivative(j, harmonic(d, slot, q), 0.0) / static_cast<double>(options_.subharmonic);
    const int ia = slot_offset(slot) * q;
    out.segment(ia, q) += dc.real();
    if (j > 0) out.segment(ia + q, q) -= dc.imag();
  }
  return out;
}

}  // namespace hbtrack
