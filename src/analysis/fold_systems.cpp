#include "hbtrack/analysis/fold_systems.hpp"

#include <stdexcept>
#include <string>

#include "hbtrack/analysis/bordering.hpp"
#include "hbtrack/util/phase_timer.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
constexpr double kEta = 1e-6;  // relative finite-difference step of the second derivatives (paper)

// The forward-difference step along d at x (paper eq 43).
double difference_step(const VectorXd& x, const VectorXd& d) { return kEta * (x.norm() / d.norm() + kEta); }
}  // namespace

void approximate_null_vectors(const MatrixXd& j, VectorXd& right, VectorXd& left) {
  const DenseLU lu(j);
  try {
    inverse_iteration_null_vectors(
        j.rows(), [&](const VectorXd& y) { return lu.solve(y); }, [&](const VectorXd& y) { return lu.solve_transposed(y); }, right, left);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("fold: ") + e.what());
  }
}

VectorXd FoldSystem::start_at(const VectorXd& x, double omega, double gamma) {
  hbm_.set_parameter(parameter_, gamma);
  VectorXd r;
  MatrixXd j;
  hbm_.evaluate(x, omega, r, &j, nullptr);
  VectorXd right, left;
  approximate_null_vectors(j, right, left);
  return start(x, omega, right, left);
}

FoldSystem::FoldSystem(const HarmonicBalance& hbm, int parameter, const FoldScales& scales)
    : hbm_(hbm), parameter_(parameter), linear_in_parameter_(parameter == hbm.amplitude_parameter()), scales_(scales), q_(hbm.unknowns()) {
  if (parameter < 0 || parameter >= hbm.parameters().size()) throw std::invalid_argument("fold: parameter index out of range");
  // The fold's second derivatives (adjoint products) need the element's own law.
  hbm.refuse_residual_elements("limit-point tracking");
}

VectorXd FoldSystem::unknown_scale(const VectorXd& u) const {
  // Displacements: the current amplitude, floored (as the NFRC's adaptive unit); then omega.
  VectorXd s(size());
  const double amplitude = u.size() ? harmonics(u).cwiseAbs().maxCoeff() : 0.0;
  s.head(q_).setConstant(std::max(scales_.length, amplitude));
  s.tail(size() - q_).setOnes();
  s(size() - 1) = scales_.omega;
  return s;
}

void FoldSystem::evaluate_hbm(const VectorXd& x, double omega, double gamma, bool derivatives, Evaluation& e) {
  hbm_.set_parameter(parameter_, gamma);
  hbm_.evaluate(x, omega, e.r, &e.j, derivatives ? &e.r_omega : nullptr);
  if (derivatives) e.r_gamma = hbm_.parameter_derivative(x, omega, parameter_);
}

void FoldSystem::parameter_derivative_change(const VectorXd& xs, double omega, double eps, const Evaluation& base, VectorXd& out) {
  if (linear_in_parameter_)
    out.setZero(q_);
  else
    out = (hbm_.parameter_derivative(xs, omega, parameter_) - base.r_gamma) / eps;
}

void FoldSystem::along(const VectorXd& x, double omega, double gamma, const VectorXd& d, const Evaluation& base, SecondDerivatives& out) {
  const double eps = difference_step(x, d);
  const VectorXd xs = x + eps * d;
  hbm_.set_parameter(parameter_, gamma);
  hbm_.evaluate(xs, omega, shifted_.r, &shifted_.j, &shifted_.r_omega);
  out.j = (shifted_.j - base.j) / eps;
  out.r_omega = (shifted_.r_omega - base.r_omega) / eps;
  parameter_derivative_change(xs, omega, eps, base, out.r_gamma);
}

void FoldSystem::along_left(const VectorXd& x, double omega, double gamma, const VectorXd& d, const VectorXd& w, const Evaluation& base,
                            LeftSecondDerivatives& out) {
  const double eps = difference_step(x, d);
  const VectorXd xs = x + eps * d;
  hbm_.set_parameter(parameter_, gamma);
  // R_x = Zr(omega) + J_nl(x) and R_omega = Zr'(omega) x - amplitude Fr'(omega) + df_nl/d(omega):
  // only the nonlinear forces' parts are differenced, the linear one along d is exact.
  const double base_omega = hbm_.nonlinear_adjoint_products(x, omega, w, base_product_);
  const double shifted_omega = hbm_.nonlinear_adjoint_products(xs, omega, w, out.jacobian_transpose_w);
  out.jacobian_transpose_w = (out.jacobian_transpose_w - base_product_) / eps;
  out.omega = (shifted_omega - base_omega) / eps + w.dot(hbm_.linear_omega_derivative(d, omega));
  parameter_derivative_change(xs, omega, eps, base, shifted_.r_gamma);
  out.gamma = w.dot(shifted_.r_gamma);
}

// ---- extended system ---------------------------------------------------------------------

VectorXd ExtendedFoldSystem::start(const VectorXd& x, double omega, const VectorXd& right, const VectorXd&) {
  VectorXd u(size());
  u << x, right.normalized(), omega;
  return u;
}

VectorXd ExtendedFoldSystem::unknown_scale(const VectorXd& u) const {
  VectorXd s = FoldSystem::unknown_scale(u);
  s.segment(q_, q_).setOnes();  // the unit null vector
  return s;
}

void ExtendedFoldSystem::evaluate(const VectorXd& u, double gamma, VectorXd& r, MatrixXd* jacobian, VectorXd* r_gamma) {
  const VectorXd x = u.head(q_), phi = u.segment(q_, q_);
  const double omega = u(2 * q_);
  Evaluation& e = base_;
  evaluate_hbm(x, omega, gamma, jacobian != nullptr, e);
  // Rows in force units: R, L R_x phi, F (phi^T phi - 1).
  const double length = scales_.length, force = scales_.force;
  r.resize(size());
  r.head(q_) = e.r;
  r.segment(q_, q_) = length * (e.j * phi);
  r(2 * q_) = force * (phi.squaredNorm() - 1.0);
  if (!jacobian) return;
  SecondDerivatives& s = second_;
  along(x, omega, gamma, phi, e, s);
  jacobian->setZero(size(), size());
  jacobian->topLeftCorner(q_, q_) = e.j;
  jacobian->block(0, 2 * q_, q_, 1) = e.r_omega;
  jacobian->block(q_, 0, q_, q_) = length * s.j;
  jacobian->block(q_, q_, q_, q_) = length * e.j;
  jacobian->block(q_, 2 * q_, q_, 1) = length * s.r_omega;
  jacobian->block(2 * q_, q_, 1, q_) = 2.0 * force * phi.transpose();
  if (r_gamma) {
    r_gamma->resize(size());
    r_gamma->head(q_) = e.r_gamma;
    r_gamma->segment(q_, q_) = length * s.r_gamma;
    (*r_gamma)(2 * q_) = 0.0;
  }
}

// ---- minimally augmented (bordered) system ---------------------------------------------------

VectorXd BorderedFoldSystem::start(const VectorXd& x, double omega, const VectorXd& right, const VectorXd& left) {
  c_ = right.normalized();
  b_ = left.normalized();
  last_u_.resize(0);
  VectorXd u(size());
  u << x, omega;
  return u;
}

void BorderedFoldSystem::null_vectors(const MatrixXd& j, bool left, bool refine) {
  MatrixXd& a = border_matrix_;
  fill_bordered_matrix(j, b_, c_, a);
  const ScopedPhase timing(Phase::factorization);
  has_left_ = left;
  if (refine && !left && border_lu_.size() == q_ + 1 && refine_right_null_vector()) return;
  border_lu_.compute(a);
  ++border_factorizations_;
  VectorXd e = VectorXd::Zero(q_ + 1);
  e(q_) = 1.0;
  const VectorXd right = border_lu_.solve(e);
  v_ = right.head(q_);
  g_ = right(q_);
  if (left) w_ = border_lu_.solve_transposed(e).head(q_);  // the left null vector reuses the factors
}

bool BorderedFoldSystem::refine_right_null_vector() {
  // [v; g] solves A z = e_q for A = border_matrix_, refined from the factors of an earlier one.
  if (!refine_last_unit_solution(border_lu_, border_matrix_, solution_, correction_)) return false;
  v_ = solution_.head(q_);
  g_ = solution_(q_);
  return true;
}

void BorderedFoldSystem::evaluate(const VectorXd& u, double gamma, VectorXd& r, MatrixXd* jacobian, VectorXd* r_gamma) {
  if (b_.size() != q_) throw std::logic_error("BorderedFoldSystem: start() sets the borders first");
  const VectorXd x = u.head(q_);
  const double omega = u(q_);
  Evaluation& e = base_;
  evaluate_hbm(x, omega, gamma, jacobian != nullptr, e);
  null_vectors(e.j, jacobian != nullptr, /*refine=*/jacobian == nullptr);
  last_u_ = u;
  last_gamma_ = gamma;
  // g has the units of R_x; times the length unit it weighs like a force.
  const double length = scales_.length;
  r.resize(size());
  r.head(q_) = e.r;
  r(q_) = length * g_;
  if (!jacobian) return;
  // g_z = -w^T (R_x)_z v, all from the second derivatives along v seen through w.
  LeftSecondDerivatives& s = left_second_;
  along_left(x, omega, gamma, v_, w_, e, s);
  jacobian->resize(size(), size());
  jacobian->topLeftCorner(q_, q_) = e.j;
  jacobian->topRightCorner(q_, 1) = e.r_omega;
  jacobian->bottomLeftCorner(1, q_) = -length * s.jacobian_transpose_w.transpose();
  (*jacobian)(q_, q_) = -length * s.omega;
  if (r_gamma) {
    r_gamma->resize(size());
    r_gamma->head(q_) = e.r_gamma;
    (*r_gamma)(q_) = -length * s.gamma;
  }
}

void BorderedFoldSystem::accepted(const VectorXd& u, double gamma) {
  // The continuation evaluates the Jacobian at the point it accepts last; recompute otherwise.
  if (!(has_left_ && last_u_.size() == u.size() && last_u_ == u && last_gamma_ == gamma)) {
    evaluate_hbm(u.head(q_), u(q_), gamma, false, base_);
    null_vectors(base_.j, true);
  }
  c_ = v_.normalized();
  b_ = w_.normalized();
}

void BorderedFoldSystem::restore_borders(const std::vector<VectorXd>& borders) {
  if (borders.size() != 2 || borders[0].size() != q_ || borders[1].size() != q_)
    throw std::invalid_argument("bordered fold system: the saved borders do not fit its " + std::to_string(q_) + " unknowns");
  b_ = borders[0];
  c_ = borders[1];
  last_u_.resize(0);  // v and w are recomputed with these borders at the next evaluation
  has_left_ = false;
}

}  // namespace hbtrack
