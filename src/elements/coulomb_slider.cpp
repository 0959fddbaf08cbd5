#include "coulomb_slider.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

CoulombSlider::CoulombSlider(int directions, double tangential_stiffness, double mu) : d_(directions), kt_(tangential_stiffness), mu_(mu) {
  if (d_ < 1 || d_ > 2) throw std::invalid_argument("CoulombSlider: 1 or 2 tangential directions");
}

SliderStep CoulombSlider::step(double normal, const SliderVector& x, const SliderVector& drift, const SliderVector& previous) const {
  const int q = inputs();
  SliderStep s;
  s.force = SliderVector::Zero(d_);
  s.G = SliderSquare::Zero(d_, d_);
  s.H = SliderInputs::Zero(d_, q);
  s.A = SliderSquare::Zero(d_, d_);
  s.E = SliderInputs::Zero(d_, q);
  const SliderSquare identity = SliderSquare::Identity(d_, d_);
  if (normal <= 0.0) {  // separated: the slider follows x
    s.mode = SlideMode::separated;
    s.state = x;
    s.E.middleCols(x_input(0), d_) = identity;
    return s;
  }
  const SliderVector predicted = previous - drift;
  const SliderVector trial = kt_ * (x - predicted);
  const double limit = mu_ * normal, norm = trial.norm();
  if (norm <= limit) {  // stick: T = kt (x - zeta_prev + drift)
    s.mode = SlideMode::stick;
    s.force = trial;
    s.state = predicted;
    s.G = -kt_ * identity;
    s.H.middleCols(x_input(0), d_) = kt_ * identity;
    s.H.middleCols(drift_input(0), d_) = kt_ * identity;
    s.H.col(stiffness_input()) = x - predicted;
    s.A = identity;
    s.E.middleCols(drift_input(0), d_) = -identity;
    return s;
  }
  // Slip: T = mu N g, g = T*/|T*|; across g the trial's change turns the direction.
  s.mode = SlideMode::slip;
  const SliderVector g = trial / norm;
  const SliderSquare turn = limit / norm * (identity - g * g.transpose());
  s.force = limit * g;
  s.state = x - s.force / kt_;
  s.G = -kt_ * turn;
  s.H.col(normal_input()) = mu_ * g;
  s.H.col(mu_input()) = normal * g;
  s.H.middleCols(x_input(0), d_) = kt_ * turn;
  s.H.middleCols(drift_input(0), d_) = kt_ * turn;
  // T does not depend on kt in slip (the trial's direction does not): H's kt column stays 0.
  s.A = -s.G / kt_;
  s.E = -s.H / kt_;
  s.E.middleCols(x_input(0), d_) += identity;
  s.E.col(stiffness_input()) += s.force / (kt_ * kt_);
  return s;
}

SliderSquare CoulombSlider::period_map() const {
  SliderSquare p = SliderSquare::Identity(d_, d_);
  for (const SliderStep& s : steps_) p = s.A * p;
  return p;
}

void CoulombSlider::solve_period(const VectorXd& normal, const MatrixXd& x, const VectorXd& drift) {
  const Eigen::Index n = normal.size();
  normal_ = normal;
  steps_.resize(static_cast<size_t>(n));
  anchored_ = false;
  centre_ = stick_centre(x, mu_ * normal / kt_);
  SliderVector zeta = centre_.z;
  const SliderVector drift_step = drift;
  if (normal.minCoeff() > 0.0 && drift.isZero(0.0) && centre_.margin >= 0.0) {
    anchored_ = true;
    for (Eigen::Index t = 0; t < n; ++t) steps_[static_cast<size_t>(t)] = step(normal(t), x.row(t).transpose(), drift_step, zeta);
    return;
  }
  // Round-off of a pass: a few ulps of the largest quantity, per step.
  const double scale = x.cwiseAbs().maxCoeff() + mu_ * normal.maxCoeff() / kt_ + static_cast<double>(n) * drift.cwiseAbs().maxCoeff();
  const double tolerance =
      64 * std::numeric_limits<double>::epsilon() * std::max(scale, std::numeric_limits<double>::min()) * static_cast<double>(n);
  constexpr int kMaxPasses = 200;
  for (int pass = 0;; ++pass) {
    SliderVector state = zeta;
    for (Eigen::Index t = 0; t < n; ++t) {
      steps_[static_cast<size_t>(t)] = step(normal(t), x.row(t).transpose(), drift_step, state);
      state = steps_[static_cast<size_t>(t)].state;
    }
    const SliderVector residual = state - zeta;
    if (residual.norm() <= tolerance || pass == kMaxPasses) return;
    // Newton lands on the periodic state if the stick-slip pattern holds there; late passes
    // fall back to plain iteration, which contracts, should patterns alternate.
    const Eigen::FullPivLU<MatrixXd> lu(MatrixXd(SliderSquare::Identity(d_, d_) - period_map()));
    zeta = (pass < kMaxPasses / 2 && lu.isInvertible()) ? SliderVector(zeta + lu.solve(VectorXd(residual))) : state;
  }
}

MatrixXd CoulombSlider::centre_response(const MatrixXd& dv) const {
  // z depends on x and r = mu N / kt at its support samples.
  const int q = inputs();
  MatrixXd dz = MatrixXd::Zero(d_, dv.cols());
  for (size_t s = 0; s < centre_.support.size(); ++s) {
    const Eigen::Index a = centre_.support[s];
    const double normal = normal_(a);
    const Eigen::RowVectorXd dr = (mu_ * dv.row(a * q + normal_input()) + normal * dv.row(a * q + mu_input())) / kt_ -
                                  (mu_ * normal / (kt_ * kt_)) * dv.row(a * q + stiffness_input());
    dz += centre_.dz_dx[s] * dv.middleRows(a * q + x_input(0), d_) + centre_.dz_dr[s] * dr;
  }
  return dz;
}

MatrixXd CoulombSlider::periodic_response(const MatrixXd& dv) const {
  const Eigen::Index n = static_cast<Eigen::Index>(steps_.size());
  const int q = inputs();
  MatrixXd dt(n * d_, dv.cols());
  MatrixXd state = MatrixXd::Zero(d_, dv.cols()), next(d_, dv.cols());
  // state <- A_t state + E_t (inputs at t), without temporaries.
  const auto advance = [&](const SliderStep& s, Eigen::Index t) {
    next.noalias() = s.A * state;
    next.noalias() += s.E * dv.middleRows(t * q, q);
    state.swap(next);
  };
  if (anchored_) {  // in stick all period at the centre
    state = centre_response(dv);
  } else {
    // The state after the period from a zero start, then the periodic start (I - P)^-1 of it.
    for (Eigen::Index t = 0; t < n; ++t) advance(steps_[static_cast<size_t>(t)], t);
    state = MatrixXd(SliderSquare::Identity(d_, d_) - period_map()).fullPivLu().solve(state);
  }
  for (Eigen::Index t = 0; t < n; ++t) {
    const SliderStep& s = steps_[static_cast<size_t>(t)];
    dt.middleRows(t * d_, d_).noalias() = s.H * dv.middleRows(t * q, q);
    dt.middleRows(t * d_, d_).noalias() += s.G * state;
    if (!anchored_) advance(s, t);
  }
  return dt;
}

MatrixXd CoulombSlider::periodic_response_transpose(const MatrixXd& dt) const {
  const Eigen::Index n = static_cast<Eigen::Index>(steps_.size());
  const int q = inputs();
  MatrixXd dv(n * q, dt.cols());
  // Adjoint of the state after sample t: m_t = A_(t+1)^T m_(t+1) + G_(t+1)^T w_(t+1), periodic.
  MatrixXd adjoint = MatrixXd::Zero(d_, dt.cols()), previous(d_, dt.cols());
  // adjoint <- A_t^T adjoint + G_t^T (weights at t), without temporaries.
  const auto recede = [&](const SliderStep& s, Eigen::Index t) {
    previous.noalias() = s.A.transpose() * adjoint;
    previous.noalias() += s.G.transpose() * dt.middleRows(t * d_, d_);
    adjoint.swap(previous);
  };
  if (!anchored_) {
    for (Eigen::Index t = n - 1; t >= 0; --t) recede(steps_[static_cast<size_t>(t)], t);
    adjoint = MatrixXd(SliderSquare::Identity(d_, d_) - period_map().transpose()).fullPivLu().solve(adjoint);
  }
  MatrixXd centre = MatrixXd::Zero(d_, dt.cols());  // weights on an anchored slider's centre
  for (Eigen::Index t = n - 1; t >= 0; --t) {
    const SliderStep& s = steps_[static_cast<size_t>(t)];
    const auto weights_t = dt.middleRows(t * d_, d_);
    dv.middleRows(t * q, q).noalias() = s.H.transpose() * weights_t;
    if (anchored_) {
      centre.noalias() += s.G.transpose() * weights_t;
      continue;
    }
    dv.middleRows(t * q, q).noalias() += s.E.transpose() * adjoint;
    recede(s, t);
  }
  for (size_t s = 0; anchored_ && s < centre_.support.size(); ++s) {  // the transpose of centre_response
    const Eigen::Index a = centre_.support[s];
    const Eigen::RowVectorXd dr = centre_.dz_dr[s].transpose() * centre;
    dv.middleRows(a * q + x_input(0), d_) += centre_.dz_dx[s].transpose() * centre;
    dv.row(a * q + normal_input()) += (mu_ / kt_) * dr;
    dv.row(a * q + mu_input()) += (normal_(a) / kt_) * dr;
    dv.row(a * q + stiffness_input()) -= (mu_ * normal_(a) / (kt_ * kt_)) * dr;
  }
  return dv;
}

Eigen::MatrixXd ContactSliderSensitivity::apply(const Eigen::MatrixXd& dx) const {
  const Eigen::Index n = dnormal_dx_.size();
  const int d = slider_.directions(), q = slider_.inputs();
  const MatrixXd dnormal = dnormal_dx_.asDiagonal() * dx.topRows(n);
  MatrixXd dv = MatrixXd::Zero(n * q, dx.cols());
  for (Eigen::Index t = 0; t < n; ++t) {
    dv.row(t * q + slider_.normal_input()) = dnormal.row(t);
    for (int i = 0; i < d; ++i) dv.row(t * q + slider_.x_input(i)) = dx.row((1 + i) * n + t);
  }
  const MatrixXd dt = slider_.periodic_response(dv);
  MatrixXd out(dx.rows(), dx.cols());
  out.topRows(n) = dnormal;
  for (Eigen::Index t = 0; t < n; ++t)
    for (int i = 0; i < d; ++i) out.row((1 + i) * n + t) = dt.row(t * d + i);
  return out;
}

Eigen::MatrixXd ContactSliderSensitivity::apply_transpose(const Eigen::MatrixXd& w) const {
  const Eigen::Index n = dnormal_dx_.size();
  const int d = slider_.directions(), q = slider_.inputs();
  MatrixXd wt(n * d, w.cols());
  for (Eigen::Index t = 0; t < n; ++t)
    for (int i = 0; i < d; ++i) wt.row(t * d + i) = w.row((1 + i) * n + t);
  const MatrixXd dv = slider_.periodic_response_transpose(wt);
  MatrixXd out(w.rows(), w.cols());
  for (Eigen::Index t = 0; t < n; ++t) {
    out.row(t) = dnormal_dx_(t) * (w.row(t) + dv.row(t * q + slider_.normal_input()));
    for (int i = 0; i < d; ++i) out.row((1 + i) * n + t) = dv.row(t * q + slider_.x_input(i));
  }
  return out;
}

void contact_slider_step(const CoulombSlider& slider, double normal, double dnormal_dx, const Eigen::MatrixXd& x,
                         const Eigen::VectorXd& drift, const Eigen::VectorXd& state, HistoryStep& out) {
  const int d = slider.directions();
  const SliderStep s = slider.step(normal, x.row(0).tail(d).transpose(), drift, state);
  out.force.resize(1 + d);
  out.force(0) = normal;
  out.force.tail(d) = s.force;
  out.state = s.state;
  out.dforce_dx.setZero(1 + d, 1 + d);
  out.dforce_dx(0, 0) = dnormal_dx;
  out.dforce_dx.bottomLeftCorner(d, 1) = s.H.col(slider.normal_input()) * dnormal_dx;
  out.dforce_dx.bottomRightCorner(d, d) = s.H.middleCols(slider.x_input(0), d);
  out.dforce_dstate.setZero(1 + d, d);
  out.dforce_dstate.bottomRows(d) = s.G;
  out.dstate_dx.resize(d, 1 + d);
  out.dstate_dx.col(0) = s.E.col(slider.normal_input()) * dnormal_dx;
  out.dstate_dx.rightCols(d) = s.E.middleCols(slider.x_input(0), d);
  out.dstate_dstate = s.A;
  out.diagonal_state = d == 1;
}

}  // namespace hbtrack
