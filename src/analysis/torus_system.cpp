#include "hbtrack/analysis/torus_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
// Why element e cannot be evaluated pointwise on the torus grid ("" when it can).
std::string torus_refusal(const NonlinearElement& e) {
  if (e.history_dependent()) return "its force depends on its past (hysteresis): a torus has no period to find its steady state on";
  if (e.uses_linear_residual()) return "it reads the linear residual (DLFT)";
  if (e.lanczos_exponent != 0.0) return "it has a Lanczos filter (lanczos = 0 for a torus)";
  return "";
}
}  // namespace

TorusSystem::TorusSystem(const HarmonicBalance& hbm, TorusBasis basis, const FoldScales& scales)
    : hbm_(hbm), basis_(std::move(basis)), scales_(scales), dofs_(hbm.model().dofs()) {
  if (hbm_.subharmonic() != 1) throw std::invalid_argument("torus: harmonic_balance.subharmonic must be 1");
  for (size_t i = 0; i < hbm_.elements().size(); ++i)
    if (const std::string why = torus_refusal(*hbm_.elements()[i]); !why.empty())
      throw std::invalid_argument("torus: elements[" + std::to_string(i) + "] (" + hbm_.elements()[i]->type() + "): " + why);
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
  const MatrixXd &m = model.mass, &c = model.damping, &k = model.stiffness;
  const double omega2 = u(harmonic_unknowns());
  const int n = dofs_, w2 = harmonic_unknowns();
  r.segment(0, n).noalias() += k * u.segment(0, n);
  if (jacobian) jacobian->block(0, 0, n, n) += k;
  for (int p = 1; p < basis_.pairs(); ++p) {
    const auto [k1, k2] = basis_.pair(p);
    const double w = k1 * omega + k2 * omega2;
    const int ia = index(TorusBasis::cosine(p), 0), ib = index(TorusBasis::sine(p), 0);
    const VectorXd a = u.segment(ia, n), b = u.segment(ib, n);
    const MatrixXd stiffness = k - w * w * m;
    r.segment(ia, n).noalias() += stiffness * a + w * (c * b);
    r.segment(ib, n).noalias() += stiffness * b - w * (c * a);
    if (!jacobian) continue;
    jacobian->block(ia, ia, n, n) += stiffness;
    jacobian->block(ib, ib, n, n) += stiffness;
    jacobian->block(ia, ib, n, n) += w * c;
    jacobian->block(ib, ia, n, n) -= w * c;
    // d/dOmega, times dOmega/domega2 = k2 and dOmega/domega = k1.
    const VectorXd da = -2.0 * w * (m * a) + c * b, db = -2.0 * w * (m * b) - c * a;
    jacobian->block(ia, w2, n, 1) += k2 * da;
    jacobian->block(ib, w2, n, 1) += k2 * db;
    if (r_omega) {
      r_omega->segment(ia, n) += k1 * da;
      r_omega->segment(ib, n) += k1 * db;
    }
  }
  // The forcing, on the pairs (k, 0).
  const double amplitude = hbm_.parameter_values()[static_cast<size_t>(hbm_.amplitude_parameter())];
  const double g = model.forcing_growth.factor(omega), dg = model.forcing_growth.derivative(omega);
  for (const HarmonicForce& f : model.forcing) {
    if (f.order == 0) {
      r.segment(0, n) -= amplitude * g * f.cos_part;
      if (r_omega) r_omega->segment(0, n) -= amplitude * dg * f.cos_part;
      continue;
    }
    const int p = basis_.find_pair(f.order, 0);
    const int ia = index(TorusBasis::cosine(p), 0), ib = index(TorusBasis::sine(p), 0);
    r.segment(ia, n) -= amplitude * g * f.cos_part;
    r.segment(ib, n) -= amplitude * g * f.sin_part;
    if (r_omega) {
      r_omega->segment(ia, n) -= amplitude * dg * f.cos_part;
      r_omega->segment(ib, n) -= amplitude * dg * f.sin_part;
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
      local_x_.col(i) = x_samples_.col(element->dofs[static_cast<size_t>(i)]);
      local_v_.col(i) = v_samples_.col(element->dofs[static_cast<size_t>(i)]);
    }
    element->evaluate(local_x_, local_v_, omega, element->property_values(hbm_.parameter_values()), response, false);
    const MatrixXd forces = analysis * response.force;  // nc x k
    const bool velocity = element->depends_on_velocity() && response.dforce_dv.size() > 0;
    for (int i = 0; i < k; ++i) {
      const int di = element->dofs[static_cast<size_t>(i)];
      for (int c = 0; c < nc; ++c) r(index(c, di)) += forces(c, i);
      if (!jacobian) continue;
      VectorXd by_omega2 = VectorXd::Zero(basis_.grid()), by_omega = VectorXd::Zero(basis_.grid());
      if (r_omega && element->depends_on_omega() && response.dforce_domega.size() > 0) by_omega = response.dforce_domega.col(i);
      for (int j = 0; j < k; ++j) {
        const int dj = element->dofs[static_cast<size_t>(j)];
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
