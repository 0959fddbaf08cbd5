// The harmonic balance's side of elements that read the linear residual at their dofs (the
// dynamic Lagrangian frequency/time method, NonlinearElement::uses_linear_residual): handing
// them the samples of r_lin = Zr x - amplitude Fr, and chaining d f / d r_lin with r_lin's own
// derivatives, Zr (the Jacobian's linear rows), d r_lin / d omega and d r_lin / d amplitude.
#include <stdexcept>

#include "hbtrack/hbm/harmonic_balance_system.hpp"
#include "hbtrack/util/dense_product.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

void HarmonicBalanceSystem::refuse_residual_elements(const std::string& analysis) const {
  for (const auto& e : elements_)
    if (e->uses_linear_residual())
      throw std::invalid_argument(
          analysis + " does not support element " + e->type() +
          " with law = \"dlft\" (its forces are Lagrange multipliers of the harmonic balance): use law = \"penalty\"");
}

VectorXd HarmonicBalanceSystem::linear_residual(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const VectorXd& x,
                                                double omega) const {
  VectorXd r = VectorXd::Zero(unknowns());
  condenser_->update(omega, ws.condensed_);
  add_condensed_linear_part(p[static_cast<size_t>(amplitude_index_)], omega, ws.condensed_, x, r, nullptr, nullptr);
  return r;
}

void HarmonicBalanceSystem::evaluate_element(const ParameterValues& p, HarmonicBalanceWorkspace& ws, size_t e, double omega,
                                             const VectorXd& r_lin, bool want_property_derivatives) const {
  const NonlinearElement& element = *elements_[e];
  const ElementSlot& s = slots_[e];
  ElementState& state = ws.elements_[e];
  const std::vector<double> props = element.property_values(p);
  if (!element.uses_linear_residual()) {
    element.evaluate(state.x, state.v, element_frequency(element, omega, options_.subharmonic), props, state.response,
                     want_property_derivatives);
    return;
  }
  const int q = retained_dofs();
  const int k = element.local_dofs();
  MatrixXd coefficients(basis_.coefficients(), k);
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < basis_.coefficients(); ++c) coefficients(c, i) = r_lin(c * q + s.columns[static_cast<size_t>(i)]);
  state.r.noalias() = basis_.synthesis() * coefficients;
  element.evaluate_with_residual(state.x, state.r, element_frequency(element, omega, options_.subharmonic), props, state.response,
                                 want_property_derivatives);
}

void HarmonicBalanceSystem::add_residual_response(const HarmonicBalanceWorkspace& ws, size_t e, const VectorXd& v, VectorXd& out) const {
  const ElementSlot& s = slots_[e];
  const int q = retained_dofs(), nc = basis_.coefficients(), n = basis_.samples();
  const int k = static_cast<int>(s.columns.size());
  MatrixXd coefficients(nc, k);
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < nc; ++c) coefficients(c, i) = v(c * q + s.columns[static_cast<size_t>(i)]);
  const MatrixXd samples = basis_.synthesis() * coefficients;  // N x k: column i at rows i N ..
  const MatrixXd response = ws.elements_[e].response.residual_operator->apply(Eigen::Map<const VectorXd>(samples.data(), samples.size()));
  const MatrixXd harmonics = basis_.analysis() * Eigen::Map<const MatrixXd>(response.data(), n, k);
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < nc; ++c) out(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * harmonics(c, i);
}

void HarmonicBalanceSystem::add_residual_coupling(const HarmonicBalanceWorkspace& ws, size_t e, const MatrixXd& linear_jacobian,
                                                  MatrixXd& jacobian) const {
  const ElementSlot& s = slots_[e];
  const int q = retained_dofs(), nc = basis_.coefficients(), n = basis_.samples();
  const int k = static_cast<int>(s.columns.size());
  // The linear Jacobian's rows of the element's dofs, ordered (dof, coefficient).
  MatrixXd rows(static_cast<Eigen::Index>(k) * nc, linear_jacobian.cols());
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < nc; ++c) rows.row(i * nc + c) = linear_jacobian.row(c * q + s.columns[static_cast<size_t>(i)]);
  // Gamma^-1 (d f_i / d r_j) Gamma, one input dof at a time, times those rows.
  MatrixXd coupling = MatrixXd::Zero(rows.rows(), rows.cols());
  for (int j = 0; j < k; ++j) {
    MatrixXd perturbation = MatrixXd::Zero(static_cast<Eigen::Index>(n) * k, nc);
    perturbation.middleRows(static_cast<Eigen::Index>(j) * n, n) = basis_.synthesis();
    const MatrixXd response = ws.elements_[e].response.residual_operator->apply(perturbation);
    for (int i = 0; i < k; ++i) {
      const MatrixXd block = basis_.analysis() * response.middleRows(static_cast<Eigen::Index>(i) * n, n);
      coupling.middleRows(i * nc, nc).noalias() += block * rows.middleRows(j * nc, nc);
    }
  }
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < nc; ++c) jacobian.row(c * q + s.columns[static_cast<size_t>(i)]) += s.sigma(c) * coupling.row(i * nc + c);
}

}  // namespace hbtrack
