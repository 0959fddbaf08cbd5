#include "hbtrack/analysis/torus_system.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
using Complex = std::complex<double>;
using Eigen::VectorXcd;

std::vector<int> retained_or_every_dof(const StructuralModel& model, std::vector<int> retained) {
  if (!retained.empty()) return retained;
  std::vector<int> every(static_cast<size_t>(model.dofs()));
  for (int d = 0; d < model.dofs(); ++d) every[static_cast<size_t>(d)] = d;
  return every;
}

// Why element e cannot be evaluated pointwise on the torus grid ("" when it can).
std::string torus_refusal(const NonlinearElement& e) {
  if (e.history_dependent()) return "its force depends on its past (hysteresis): a torus has no period to find its steady state on";
  if (e.uses_linear_residual()) return "it reads the linear residual (DLFT)";
  if (e.lanczos_exponent != 0.0) return "it has a Lanczos filter (lanczos = 0 for a torus)";
  return "";
}
}  // namespace

TorusSystem::TorusSystem(const HarmonicBalance& hbm, TorusBasis basis, const FoldScales& scales, std::vector<int> retained)
    : hbm_(hbm), basis_(std::move(basis)), scales_(scales), linear_(hbm.model(), retained_or_every_dof(hbm.model(), retained)) {
  retained_ = linear_.retained();
  dofs_ = static_cast<int>(retained_.size());
  column_of_.assign(static_cast<size_t>(hbm_.model().dofs()), -1);
  for (int k = 0; k < dofs_; ++k) column_of_[static_cast<size_t>(retained_[static_cast<size_t>(k)])] = k;
  if (hbm_.subharmonic() != 1) throw std::invalid_argument("torus: harmonic_balance.subharmonic must be 1");
  for (size_t i = 0; i < hbm_.elements().size(); ++i)
    if (const std::string why = torus_refusal(*hbm_.elements()[i]); !why.empty())
      throw std::invalid_argument("torus: elements[" + std::to_string(i) + "] (" + hbm_.elements()[i]->type() + "): " + why);
  for (const auto& element : hbm_.elements())
    for (const int d : element->dofs)
      if (column(d) < 0) throw std::invalid_argument("torus: the retained dofs miss dof " + std::to_string(d) + " of an element");
  for (const HarmonicForce& f : hbm_.model().forcing)
    if (f.order > basis_.h1())
      throw std::invalid_argument("torus: the forcing's harmonic " + std::to_string(f.order) +
                                  " is above the torus' H1 = " + std::to_string(basis_.h1()));
  for (int p = 1; p < basis_.pairs(); ++p)
    if (basis_.pair(p).second != 0) {
      phase_pair_ = p;
      break;
    }
}

void TorusSystem::set_phase_condition(int pair, int dof) {
  if (pair < 1 || pair >= basis_.pairs() || basis_.pair(pair).second == 0 || dof < 0 || dof >= dofs_)
    throw std::invalid_argument("torus: the phase condition needs a pair with k2 != 0 and a dof of the model");
  phase_pair_ = pair;
  phase_dof_ = dof;
}

MatrixXd TorusSystem::samples(const VectorXd& u, const TorusBasis& grid_basis) const {
  const Eigen::Map<const MatrixXd> x(u.data(), dofs_, basis_.coefficients());
  return grid_basis.synthesis() * x.transpose();
}

VectorXd TorusSystem::project(const MatrixXd& grid_samples) const {
  const MatrixXd coefficients = basis_.analysis() * grid_samples;  // nc x n
  VectorXd out(harmonic_unknowns());
  Eigen::Map<MatrixXd>(out.data(), dofs_, basis_.coefficients()) = coefficients.transpose();
  return out;
}

void TorusSystem::add_linear_part(const VectorXd& u, double omega, VectorXd& r, MatrixXd* jacobian, VectorXd* r_omega) const {
  const StructuralModel& model = hbm_.model();
  const double omega2 = u(harmonic_unknowns());
  const int n = dofs_, w2 = harmonic_unknowns();
  const double amplitude = hbm_.parameter_values()[static_cast<size_t>(hbm_.amplitude_parameter())];
  const double g = model.forcing_growth.factor(omega), dg = model.forcing_growth.derivative(omega);
  // The unit forcing of each pair (k, 0) as complex amplitudes cos - i sin (the mean: its value).
  std::vector<VectorXcd> forcing(static_cast<size_t>(basis_.pairs()));
  for (const HarmonicForce& f : model.forcing) {
    const int p = f.order == 0 ? 0 : basis_.find_pair(f.order, 0);
    VectorXcd& at = forcing[static_cast<size_t>(p)];
    if (at.size() == 0) at = VectorXcd::Zero(model.dofs());
    at += f.cos_part.cast<Complex>();
    if (f.order != 0) at -= Complex(0, 1) * f.sin_part.cast<Complex>();
  }
  for (int p = 0; p < basis_.pairs(); ++p) {
    const auto [k1, k2] = basis_.pair(p);
    const double w = k1 * omega + k2 * omega2;
    // Coefficients as z = a - i b: the residual's rows are r_a - i r_b = Zr z - amplitude g Fr.
    const int ia = p == 0 ? 0 : index(TorusBasis::cosine(p), 0), ib = p == 0 ? -1 : index(TorusBasis::sine(p), 0);
    VectorXcd z = u.segment(ia, n).cast<Complex>();
    if (p > 0) z -= Complex(0, 1) * u.segment(ib, n).cast<Complex>();
    const VectorXcd* unit_force = forcing[static_cast<size_t>(p)].size() ? &forcing[static_cast<size_t>(p)] : nullptr;
    const PairBalance b = linear_.balance(w, z, unit_force, amplitude * g, jacobian != nullptr);
    r.segment(ia, n) += b.residual.real();
    if (p > 0) r.segment(ib, n) -= b.residual.imag();
    if (unit_force && r_omega && dg != 0) {
      r_omega->segment(ia, n) -= amplitude * dg * b.reduced_force.real();
      if (p > 0) r_omega->segment(ib, n) += amplitude * dg * b.reduced_force.imag();
    }
    if (!jacobian) continue;
    jacobian->block(ia, ia, n, n) += b.stiffness.real();
    if (p == 0) continue;
    jacobian->block(ib, ib, n, n) += b.stiffness.real();
    jacobian->block(ia, ib, n, n) += b.stiffness.imag();
    jacobian->block(ib, ia, n, n) -= b.stiffness.imag();
    // d/dOmega at fixed coefficients, times dOmega/domega2 = k2 and dOmega/domega = k1.
    jacobian->block(ia, w2, n, 1) += k2 * b.frequency_derivative.real();
    jacobian->block(ib, w2, n, 1) -= k2 * b.frequency_derivative.imag();
    if (r_omega) {
      r_omega->segment(ia, n) += k1 * b.frequency_derivative.real();
      r_omega->segment(ib, n) -= k1 * b.frequency_derivative.imag();
    }
  }
}

void TorusSystem::add_element_forces(const VectorXd& u, double omega, VectorXd& r, MatrixXd* jacobian, VectorXd* r_omega) {
  const int nc = basis_.coefficients(), w2 = harmonic_unknowns();
  const double omega2 = u(w2);
  const Eigen::Map<const MatrixXd> x(u.data(), dofs_, nc);
  velocity_synthesis_ = omega * basis_.theta1_derivative() + omega2 * basis_.theta2_derivative();
  x_samples_.noalias() = basis_.synthesis() * x.transpose();
  v_samples_.noalias() = velocity_synthesis_ * x.transpose();
  const MatrixXd& analysis = basis_.analysis();
  ElementResponse response;
  for (const auto& element : hbm_.elements()) {
    const int k = element->local_dofs();
    local_x_.resize(basis_.grid(), k);
    local_v_.resize(basis_.grid(), k);
    for (int i = 0; i < k; ++i) {
      local_x_.col(i) = x_samples_.col(column(element->dofs[static_cast<size_t>(i)]));
      local_v_.col(i) = v_samples_.col(column(element->dofs[static_cast<size_t>(i)]));
    }
    element->evaluate(local_x_, local_v_, omega, element->property_values(hbm_.parameter_values()), response, false);
    const MatrixXd forces = analysis * response.force;  // nc x k
    const bool velocity = element->depends_on_velocity() && response.dforce_dv.size() > 0;
    for (int i = 0; i < k; ++i) {
      const int di = column(element->dofs[static_cast<size_t>(i)]);
      for (int c = 0; c < nc; ++c) r(index(c, di)) += forces(c, i);
      if (!jacobian) continue;
      VectorXd by_omega2 = VectorXd::Zero(basis_.grid()), by_omega = VectorXd::Zero(basis_.grid());
      if (r_omega && element->depends_on_omega() && response.dforce_domega.size() > 0) by_omega = response.dforce_domega.col(i);
      for (int j = 0; j < k; ++j) {
        const int dj = column(element->dofs[static_cast<size_t>(j)]);
        weighted_ = basis_.synthesis().array().colwise() * response.dforce_dx.col(i + k * j).array();
        if (velocity) {
          const auto dv = response.dforce_dv.col(i + k * j).array();
          weighted_.array() += velocity_synthesis_.array().colwise() * dv;
          by_omega2.array() += dv * (basis_.theta2_derivative() * x.row(dj).transpose()).array();
          if (r_omega) by_omega.array() += dv * (basis_.theta1_derivative() * x.row(dj).transpose()).array();
        }
        block_.noalias() = analysis * weighted_;
        for (int cc = 0; cc < nc; ++cc)
          for (int c = 0; c < nc; ++c) (*jacobian)(index(c, di), index(cc, dj)) += block_(c, cc);
      }
      const VectorXd projected_omega2 = analysis * by_omega2;
      for (int c = 0; c < nc; ++c) (*jacobian)(index(c, di), w2) += projected_omega2(c);
      if (r_omega) {
        const VectorXd projected_omega = analysis * by_omega;
        for (int c = 0; c < nc; ++c) (*r_omega)(index(c, di)) += projected_omega(c);
      }
    }
  }
}

void TorusSystem::evaluate(const VectorXd& u, double omega, VectorXd& r, MatrixXd* jacobian, VectorXd* r_omega) {
  if (u.size() != size())
    throw std::logic_error("TorusSystem: u has " + std::to_string(u.size()) + " entries, not " + std::to_string(size()));
  const int m = harmonic_unknowns();
  r = VectorXd::Zero(size());
  if (jacobian) jacobian->setZero(size(), size());
  if (r_omega) r_omega->setZero(size());
  add_linear_part(u, omega, r, jacobian, r_omega);
  add_element_forces(u, omega, r, jacobian, r_omega);
  // The phase condition, in force units like the balance.
  const double weight = scales_.force / scales_.length;
  const int phase = index(TorusBasis::sine(phase_pair_), phase_dof_);
  r(m) = weight * u(phase);
  if (jacobian) (*jacobian)(m, phase) = weight;
}

VectorXd TorusSystem::unknown_scale(const VectorXd& u) const {
  VectorXd s(size());
  const double amplitude = u.size() == size() ? u.head(harmonic_unknowns()).cwiseAbs().maxCoeff() : 0.0;
  s.head(harmonic_unknowns()).setConstant(std::max(scales_.length, amplitude));
  s(harmonic_unknowns()) = scales_.omega;
  return s;
}

}  // namespace hbtrack
