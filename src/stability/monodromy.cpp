#include "hbtrack/stability/monodromy.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace hbtrack {

using Eigen::MatrixXd;

FloquetResult monodromy_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double forcing_omega, int steps) {
  const StructuralModel& model = hbm.model();
  const int n = model.dofs();
  const int h = hbm.basis().harmonics();  // the expanded solution's dense layout 0..H
  // The solution's period is that of the basis' fundamental (omega / nu); the elements see omega.
  const double omega = hbm.fundamental(forcing_omega);
  const double period = 2.0 * std::numbers::pi / omega;
  // Displacement and velocity of every dof at the 2*steps+1 stage times (steps and midpoints).
  const int samples = 2 * steps + 1;
  const Eigen::VectorXd full = hbm.expand(x, forcing_omega);
  const Eigen::Map<const MatrixXd> coeffs(full.data(), n, 2 * h + 1);
  MatrixXd basis(samples, 2 * h + 1), dbasis(samples, 2 * h + 1);
  for (int s = 0; s < samples; ++s) {
    const double tau = 2.0 * std::numbers::pi * s / (samples - 1);
    basis(s, 0) = 0.5;
    dbasis(s, 0) = 0.0;
    for (int j = 1; j <= h; ++j) {
      basis(s, 2 * j - 1) = std::cos(j * tau);
      basis(s, 2 * j) = std::sin(j * tau);
      dbasis(s, 2 * j - 1) = -j * omega * std::sin(j * tau);
      dbasis(s, 2 * j) = j * omega * std::cos(j * tau);
    }
  }
  const MatrixXd disp = basis * coeffs.transpose(), vel = dbasis * coeffs.transpose();  // samples x n

  // Linearised element stiffness and damping at every stage time, scattered to model dofs.
  std::vector<MatrixXd> fx(static_cast<size_t>(samples), MatrixXd::Zero(n, n)), fv(static_cast<size_t>(samples), MatrixXd::Zero(n, n));
  for (const auto& element : hbm.elements()) {
    if (element->history_dependent())
      throw std::invalid_argument("element " + element->type() + " depends on its history: monodromy stability does not support it (use stability.method = \"hill\")");
    const int k = element->local_dofs();
    MatrixXd xl(samples, k), vl(samples, k);
    for (int i = 0; i < k; ++i) {
      xl.col(i) = disp.col(element->dofs[static_cast<size_t>(i)]);
      vl.col(i) = vel.col(element->dofs[static_cast<size_t>(i)]);
    }
    ElementResponse resp;
    // As the harmonic balance hands it (the samples span the period of omega / nu).
    element->evaluate(xl, vl, element->depends_on_omega() ? forcing_omega : omega, element->property_values(hbm.parameters()), resp, false);
    for (int s = 0; s < samples; ++s)
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const int ri = element->dofs[static_cast<size_t>(i)], cj = element->dofs[static_cast<size_t>(j)];
          fx[static_cast<size_t>(s)](ri, cj) += resp.dforce_dx(s, i + k * j);
          if (resp.dforce_dv.size() > 0) fv[static_cast<size_t>(s)](ri, cj) += resp.dforce_dv(s, i + k * j);
        }
  }
  const MatrixXd m_inv = model.mass.llt().solve(MatrixXd::Identity(n, n));
  auto system = [&](int s) {  // A(t) of z' = A z, z = [y; y']
    MatrixXd a = MatrixXd::Zero(2 * n, 2 * n);
    a.topRightCorner(n, n).setIdentity();
    a.bottomLeftCorner(n, n) = -m_inv * (model.stiffness + fx[static_cast<size_t>(s)]);
    a.bottomRightCorner(n, n) = -m_inv * (model.damping + fv[static_cast<size_t>(s)]);
    return a;
  };
  const double dt = period / steps;
  MatrixXd phi = MatrixXd::Identity(2 * n, 2 * n);
  MatrixXd a0 = system(0);
  for (int step = 0; step < steps; ++step) {
    const MatrixXd a_mid = system(2 * step + 1), a1 = system(2 * step + 2);
    const MatrixXd k1 = a0 * phi;
    const MatrixXd k2 = a_mid * (phi + 0.5 * dt * k1);
    const MatrixXd k3 = a_mid * (phi + 0.5 * dt * k2);
    const MatrixXd k4 = a1 * (phi + dt * k3);
    phi += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    a0 = a1;
  }
  FloquetResult r;
  r.method = "monodromy";
  const Eigen::VectorXcd mu = Eigen::EigenSolver<MatrixXd>(phi, false).eigenvalues();
  r.exponents = mu.array().log() / period;
  finish_floquet(r, omega, 1e-9 * omega);
  r.multipliers = mu;  // exact, not re-exponentiated
  return r;
}

}  // namespace hbtrack
