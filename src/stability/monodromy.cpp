#include "hbtrack/stability/monodromy.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "hbtrack/util/dense_eigen.hpp"

namespace hbtrack {

using Eigen::MatrixXd;

namespace {

// A history element along the orbit: its internal variables at the step ends (periodic_history
// of the step samples) and the return mapping at each stage, evaluated as the integration goes:
// from the variables after step n - 1 to x(t_n) at the step's start (the step that arrives
// there, so a slider slipping at t_n counts as slipping), from those after step n to the
// midpoint and to t_(n+1).
class HistoryTrack {
 public:
  HistoryTrack(const NonlinearElement& element, std::vector<double> props, const MatrixXd& disp, double omega, double dt, int offset)
      : element_(element), props_(std::move(props)), omega_(omega), dt_(dt), offset_(offset), local_(disp.rows(), element.local_dofs()) {
    for (int i = 0; i < element.local_dofs(); ++i) local_.col(i) = disp.col(element.dofs[static_cast<size_t>(i)]);
    steps_ = static_cast<int>(disp.rows() - 1) / 2;
    MatrixXd ends(steps_, element.local_dofs());
    for (int n = 0; n < steps_; ++n) ends.row(n) = local_.row(2 * n);
    states_ = element.periodic_history(ends, omega, props_);
    arrive(0, start_);
  }
  const NonlinearElement& element() const { return element_; }
  int offset() const { return offset_; }
  int size() const { return element_.history_state_size(); }
  // Linearisations at the stages of step n; after next_step(n), start() is that of step n + 1.
  const HistoryStep& start() const { return start_; }
  const HistoryStep& mid() const { return mid_; }
  const HistoryStep& end() const { return end_; }
  void prepare_step(int n) {
    element_.history_step(local_.row(2 * n + 1), states_.row(n).transpose(), 0.5 * dt_, omega_, props_, mid_);
    arrive(n + 1, end_);
  }
  void next_step() { std::swap(start_, end_); }

 private:
  // The step arriving at step end n (sample 2n) from the variables after step end n - 1.
  void arrive(int n, HistoryStep& out) const {
    element_.history_step(local_.row(2 * n), states_.row((n + steps_ - 1) % steps_).transpose(), dt_, omega_, props_, out);
  }
  const NonlinearElement& element_;
  std::vector<double> props_;
  double omega_, dt_;
  int offset_, steps_ = 0;
  MatrixXd local_;   // stage samples of the element's dofs
  MatrixXd states_;  // steps x size: the variables after each step end
  HistoryStep start_, mid_, end_;
};

// z <- dz/dx dx + dz/dz z, with a diagonal dz/dz applied by its diagonal.
void update_variables(const HistoryStep& s, const MatrixXd& dx, Eigen::Block<MatrixXd> z) {
  if (s.diagonal_state) {
    z = s.dstate_dstate.diagonal().asDiagonal() * z;
  } else {
    z = (s.dstate_dstate * z).eval();
  }
  z.noalias() += s.dstate_dx * dx;
}

// Does the step leave variable j unchanged (a stuck slider)?
bool keeps(const HistoryStep& s, int j) {
  if (s.dstate_dstate(j, j) != 1.0 || !s.dstate_dx.row(j).isZero(0.0)) return false;
  return s.diagonal_state || s.dstate_dstate.row(j).cwiseAbs().sum() == 1.0;
}

}  // namespace

FloquetResult monodromy_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double forcing_omega, int steps) {
  const StructuralModel& model = hbm.model();
  const int n = model.dofs();
  const int h = hbm.basis().harmonics();  // the expanded solution's dense layout 0..H
  // The solution's period is that of the basis' fundamental (omega / nu); the elements see omega.
  const double omega = hbm.fundamental(forcing_omega);
  const double period = 2.0 * std::numbers::pi / omega;
  const double dt = period / steps;
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

  // Linearised stiffness and damping of the pointwise elements at every stage time, scattered
  // to model dofs; the history elements are tracked along the integration.
  std::vector<MatrixXd> fx(static_cast<size_t>(samples), MatrixXd::Zero(n, n)), fv(static_cast<size_t>(samples), MatrixXd::Zero(n, n));
  std::vector<HistoryTrack> tracks;
  int m = 0;  // internal variables
  for (const auto& element : hbm.elements()) {
    const int k = element->local_dofs();
    const std::vector<double> props = element->property_values(hbm.parameters());
    if (element->history_dependent()) {
      if (element->history_state_size() == 0)
        throw std::invalid_argument(
            "element " + element->type() +
            " has no time-stepping form: monodromy stability does not support it (use stability.method = \"hill\")");
      tracks.emplace_back(*element, props, disp, omega, dt, m);
      m += element->history_state_size();
      continue;
    }
    MatrixXd xl(samples, k), vl(samples, k);
    for (int i = 0; i < k; ++i) {
      xl.col(i) = disp.col(element->dofs[static_cast<size_t>(i)]);
      vl.col(i) = vel.col(element->dofs[static_cast<size_t>(i)]);
    }
    ElementResponse resp;
    // As the harmonic balance hands it (the samples span the period of omega / nu).
    element->evaluate(xl, vl, element->depends_on_omega() ? forcing_omega : omega, props, resp, false);
    for (int s = 0; s < samples; ++s)
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const int ri = element->dofs[static_cast<size_t>(i)], cj = element->dofs[static_cast<size_t>(j)];
          fx[static_cast<size_t>(s)](ri, cj) += resp.dforce_dx(s, i + k * j);
          if (resp.dforce_dv.size() > 0) fv[static_cast<size_t>(s)](ri, cj) += resp.dforce_dv(s, i + k * j);
        }
  }
  const MatrixXd m_inv = model.mass.llt().solve(MatrixXd::Identity(n, n));
  // y' = A y + c at a stage, y = [dx; dx'], c = [0; -M^-1 df/dz z] the pull of the internal
  // variables z (frozen over a step), formed element by element: df/dz is sparse.
  MatrixXd stiffness(n, n), force(n, 2 * n + m);
  auto system = [&](int s, const HistoryStep* const* stage, MatrixXd& a) {
    stiffness = model.stiffness + fx[static_cast<size_t>(s)];
    for (size_t e = 0; e < tracks.size(); ++e) {
      const NonlinearElement& element = tracks[e].element();
      for (int i = 0; i < element.local_dofs(); ++i)
        for (int j = 0; j < element.local_dofs(); ++j)
          stiffness(element.dofs[static_cast<size_t>(i)], element.dofs[static_cast<size_t>(j)]) += stage[e]->dforce_dx(i, j);
    }
    a.setZero(2 * n, 2 * n);
    a.topRightCorner(n, n).setIdentity();
    a.bottomLeftCorner(n, n) = -m_inv * stiffness;
    a.bottomRightCorner(n, n) = -m_inv * (model.damping + fv[static_cast<size_t>(s)]);
  };
  auto pull = [&](const HistoryStep* const* stage, const MatrixXd& zeta, MatrixXd& c) {
    c.setZero(2 * n, zeta.cols());
    if (tracks.empty()) return;
    force.setZero(n, zeta.cols());
    for (size_t e = 0; e < tracks.size(); ++e) {
      const NonlinearElement& element = tracks[e].element();
      const MatrixXd local = stage[e]->dforce_dstate * zeta.middleRows(tracks[e].offset(), tracks[e].size());
      for (int i = 0; i < element.local_dofs(); ++i) force.row(element.dofs[static_cast<size_t>(i)]) += local.row(i);
    }
    c.bottomRows(n).noalias() = -m_inv * force;
  };
  std::vector<const HistoryStep*> starts(tracks.size()), mids(tracks.size()), ends(tracks.size());
  // The monodromy matrix of the state [y; z]: y by RK4 with z frozen over the step, then z by
  // the linearised return mapping at the step's end.
  const int size = 2 * n + m;
  MatrixXd phi = MatrixXd::Identity(2 * n, size);  // rows of y
  MatrixXd zeta = MatrixXd::Zero(m, size);         // rows of z
  zeta.rightCols(m).setIdentity();
  std::vector<bool> moves(static_cast<size_t>(m), false);  // does the variable ever change?
  MatrixXd a0, a_mid, a1, c0, c_mid, c1;
  for (size_t e = 0; e < tracks.size(); ++e) starts[e] = &tracks[e].start();
  system(0, starts.data(), a0);
  for (int step = 0; step < steps; ++step) {
    for (size_t e = 0; e < tracks.size(); ++e) {
      tracks[e].prepare_step(step);
      starts[e] = &tracks[e].start();
      mids[e] = &tracks[e].mid();
      ends[e] = &tracks[e].end();
    }
    system(2 * step + 1, mids.data(), a_mid);
    system(2 * step + 2, ends.data(), a1);
    pull(starts.data(), zeta, c0);
    pull(mids.data(), zeta, c_mid);
    pull(ends.data(), zeta, c1);
    const MatrixXd k1 = a0 * phi + c0;
    const MatrixXd k2 = a_mid * (phi + 0.5 * dt * k1) + c_mid;
    const MatrixXd k3 = a_mid * (phi + 0.5 * dt * k2) + c_mid;
    const MatrixXd k4 = a1 * (phi + dt * k3) + c1;
    phi += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    for (HistoryTrack& track : tracks) {
      const NonlinearElement& element = track.element();
      MatrixXd dx(element.local_dofs(), size);
      for (int i = 0; i < element.local_dofs(); ++i) dx.row(i) = phi.row(element.dofs[static_cast<size_t>(i)]);
      update_variables(track.end(), dx, zeta.middleRows(track.offset(), track.size()));
      for (int j = 0; j < track.size(); ++j)
        if (!keeps(track.end(), j)) moves[static_cast<size_t>(track.offset() + j)] = true;
      track.next_step();
    }
    std::swap(a0, a1);
  }
  // A variable that never changes (a slider stuck over the whole period) has the multiplier 1
  // exactly (its row of the monodromy matrix is the identity's): a neutral slider position, not
  // a dynamic mode. It is dropped, which leaves the stuck spring in the dynamics.
  std::vector<int> kept(static_cast<size_t>(2 * n));
  std::iota(kept.begin(), kept.end(), 0);
  for (int j = 0; j < m; ++j)
    if (moves[static_cast<size_t>(j)]) kept.push_back(2 * n + j);
  MatrixXd full_map(size, size);
  full_map << phi, zeta;
  MatrixXd reduced(kept.size(), kept.size());
  for (size_t r = 0; r < kept.size(); ++r)
    for (size_t c = 0; c < kept.size(); ++c)
      reduced(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = full_map(kept[r], kept[c]);
  Eigen::VectorXcd mu = dense_eigenvalues(reduced);
  if (mu.size() > 2 * n) {
    // A slider that slips forgets its position: its multiplier is 0 (round-off). The 2n of
    // largest modulus are the dynamic ones.
    std::vector<Eigen::Index> order(static_cast<size_t>(mu.size()));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](Eigen::Index i, Eigen::Index j) { return std::abs(mu(i)) > std::abs(mu(j)); });
    Eigen::VectorXcd largest(2 * n);
    for (int i = 0; i < 2 * n; ++i) largest(i) = mu(order[static_cast<size_t>(i)]);
    mu = largest;
  }
  FloquetResult r;
  r.method = StabilityMethod::monodromy;
  r.exponents = mu.array().log() / period;
  finish_floquet(r, omega, 1e-9 * omega);
  r.multipliers = mu;  // exact, not re-exponentiated
  return r;
}

}  // namespace hbtrack
