#include "hbtrack/analysis/critical_exponent_system.hpp"

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "hbtrack/analysis/bordering.hpp"
#include "hbtrack/stability/hill.hpp"
#include "hbtrack/util/phase_timer.hpp"

namespace hbtrack {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Eigen::VectorXd;
using Complex = std::complex<double>;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kPencilEta = 1e-6;  // relative forward-difference step, as the fold systems' (paper eq 43)

double pencil_step(double scale) { return kPencilEta * (scale + kPencilEta); }

const char* exponent_name(CriticalExponent kind) { return kind == CriticalExponent::neimark_sacker ? "Neimark-Sacker" : "period-doubling"; }

// Index of Hill's exponent that crosses at an NS (PD) point: nearest the imaginary axis among
// those whose multiplier is complex (PD: real negative; Hill's truncation leaves such a
// multiplier's argument up to 0.02 rad off pi, FloquetMonitor::classify), or -1.
Eigen::Index crossing_exponent(const FloquetResult& f, CriticalExponent kind) {
  constexpr double kRealArgument = 0.02;
  Eigen::Index best = -1;
  for (Eigen::Index i = 0; i < f.exponents.size(); ++i) {
    const double angle = std::abs(std::arg(f.multipliers(i)));
    const bool negative_real = angle >= kPi - kRealArgument;
    const bool complex = angle > kRealArgument && !negative_real;
    if (kind == CriticalExponent::neimark_sacker ? !complex : !negative_real) continue;
    if (f.exponents(i).imag() == 0.0) continue;  // the pencil's real eigenvalues: no frequency to follow
    if (best < 0 || std::abs(f.exponents(i).real()) < std::abs(f.exponents(best).real())) best = i;
  }
  return best;
}
}  // namespace

CriticalExponentSystem::CriticalExponentSystem(const HarmonicBalance& hbm, int parameter, const FoldScales& scales, CriticalExponent kind)
    : FoldSystem(hbm, parameter, scales), kind_(kind), dofs_(hbm.model().dofs()) {
  hbm.refuse_residual_elements(std::string(exponent_name(kind)) + " tracking");
  std::set<int> coupled;
  for (const auto& e : hbm.elements()) coupled.insert(e->dofs.begin(), e->dofs.end());
  coupled_.assign(coupled.begin(), coupled.end());
}

VectorXd CriticalExponentSystem::start(const VectorXd&, double, const VectorXd&, const VectorXd&) {
  throw std::logic_error("CriticalExponentSystem: start with start_at (the borders are complex)");
}

VectorXd CriticalExponentSystem::start_at(const VectorXd& x, double omega, double gamma) {
  hbm_.set_parameter(parameter_, gamma);
  const FloquetResult f = hill_floquet(hbm_, x, omega);
  const Eigen::Index k = crossing_exponent(f, kind_);
  if (k < 0) {
    std::string listed;
    for (Eigen::Index i = 0; i < f.multipliers.size(); ++i)
      listed += (i ? ", " : "") + std::to_string(std::abs(f.multipliers(i))) + " at " + std::to_string(std::arg(f.multipliers(i))) + " rad";
    throw std::runtime_error(std::string(exponent_name(kind_)) + " tracking: no multiplier of that kind at the start, omega = " +
                             std::to_string(omega) + " (multipliers " + listed + ")");
  }
  return start_at_frequency(x, omega, gamma, std::abs(f.exponents(k).imag()));
}

VectorXd CriticalExponentSystem::start_at_frequency(const VectorXd& x, double omega, double gamma, double nu) {
  hbm_.set_parameter(parameter_, gamma);
  form_pencil(x, omega, nu);
  // Eigen's complex LU has no solve with A^H here: the adjoint is factored on its own.
  const Eigen::PartialPivLU<MatrixXcd> lu(a_), lu_adjoint(a_.adjoint());
  VectorXcd right, left;
  inverse_iteration_null_vectors(
      a_.rows(), [&](const VectorXcd& y) { return lu.solve(y); }, [&](const VectorXcd& y) { return lu_adjoint.solve(y); }, right, left);
  c_ = right;
  b_ = left;
  last_u_.resize(0);
  VectorXd u(size());
  u << x, nu, omega;
  return u;
}

VectorXcd CriticalExponentSystem::mass_times(const VectorXcd& y) const {
  const MatrixXd& m = hbm_.model().mass;
  VectorXcd out(y.size());
  for (Eigen::Index b = 0; b < y.size() / dofs_; ++b) out.segment(b * dofs_, dofs_).noalias() = m * y.segment(b * dofs_, dofs_);
  return out;
}

void CriticalExponentSystem::form_pencil(const VectorXd& x, double omega, double nu) {
  hbm_.hill_matrices(x, omega, hill_j_, hill_d1_);
  a_ = hill_j_.cast<Complex>() + Complex(0, nu) * hill_d1_.cast<Complex>();
  const MatrixXd& m = hbm_.model().mass;
  for (Eigen::Index b = 0; b < a_.rows() / dofs_; ++b) a_.block(b * dofs_, b * dofs_, dofs_, dofs_) -= (nu * nu) * m.cast<Complex>();
}

Complex CriticalExponentSystem::pencil_product(const VectorXd& x, double omega, double nu) {
  hbm_.hill_matrices(x, omega, hill_j_, hill_d1_);
  const VectorXcd av = hill_j_ * v_ + Complex(0, nu) * (hill_d1_ * v_) - (nu * nu) * mass_times(v_);
  return w_.dot(av);  // dot conjugates its first argument: w^H A v
}

Complex CriticalExponentSystem::element_product(const VectorXd& x, double omega, double nu) {
  hbm_.hill_element_blocks(x, omega, coupled_, element_j_, element_d1_);
  const VectorXcd ev = element_j_ * coupled_v_ + Complex(0, nu) * (element_d1_ * coupled_v_);
  return coupled_w_.dot(ev);
}

void CriticalExponentSystem::solve_bordered(bool left) {
  const Eigen::Index n = a_.rows();
  fill_bordered_matrix(a_, b_, c_, bordered_);
  {
    const ScopedPhase timing(Phase::factorization);
    lu_.compute(bordered_);
  }
  VectorXcd e = VectorXcd::Zero(n + 1);
  e(n) = 1.0;
  const VectorXcd right = lu_.solve(e);
  v_ = right.head(n);
  g_ = right(n);
  has_left_ = left;
  // The left vector from the same factors (a second factorisation, of B^H, cost as much as the
  // first). P B = L U, so B^H w = e is U^H L^H P w = e: two triangular solves and P^T.
  // (Eigen 3.4's lu.adjoint().solve does not compile for a complex PartialPivLU.)
  if (left) {
    VectorXcd y = e;
    lu_.matrixLU().triangularView<Eigen::Upper>().adjoint().solveInPlace(y);
    lu_.matrixLU().triangularView<Eigen::UnitLower>().adjoint().solveInPlace(y);
    w_ = (lu_.permutationP().transpose() * y).head(n);
  }
}

void CriticalExponentSystem::evaluate(const VectorXd& u, double gamma, VectorXd& r, MatrixXd* jacobian, VectorXd* r_gamma) {
  if (b_.size() == 0) throw std::logic_error("CriticalExponentSystem: start_at() sets the borders first");
  const VectorXd x = u.head(q_);
  const double nu = u(q_), omega = u(q_ + 1);
  Evaluation& e = base_;
  evaluate_hbm(x, omega, gamma, jacobian != nullptr, e);
  form_pencil(x, omega, nu);
  solve_bordered(jacobian != nullptr);
  last_u_ = u;
  last_gamma_ = gamma;
  // g has the units of the pencil (of R_x); times the length unit it weighs like a force.
  const double length = scales_.length;
  r.resize(size());
  r.head(q_) = e.r;
  r(q_) = length * g_.real();
  r(q_ + 1) = length * g_.imag();
  if (!jacobian) return;
  // g_z = -w^H A_z v: A_nu exactly, the others by differences of w^H A v.
  const VectorXcd d1v = hill_d1_ * v_;
  const Complex g_nu = -w_.dot(Complex(0, 1) * d1v - (2.0 * nu) * mass_times(v_));
  const Complex base = pencil_product(x, omega, nu);
  jacobian->setZero(size(), size());
  jacobian->topLeftCorner(q_, q_) = e.j;
  jacobian->block(0, q_ + 1, q_, 1) = e.r_omega;
  // v and w on the elements' dofs (row b c + i of their blocks: coefficient b of coupled dof i).
  const Eigen::Index c = static_cast<Eigen::Index>(coupled_.size());
  coupled_v_.resize(c * hbm_.basis().coefficients());
  coupled_w_.resize(coupled_v_.size());
  for (Eigen::Index b = 0; b < hbm_.basis().coefficients(); ++b)
    for (Eigen::Index i = 0; i < c; ++i) {
      coupled_v_(b * c + i) = v_(b * dofs_ + coupled_[static_cast<size_t>(i)]);
      coupled_w_(b * c + i) = w_(b * dofs_ + coupled_[static_cast<size_t>(i)]);
    }
  const Complex element_base = element_product(x, omega, nu);
  const double x_step = pencil_step(x.norm());
  VectorXd shifted = x;
  for (int k = 0; k < q_; ++k) {
    shifted(k) += x_step;
    const Complex g_k = -(element_product(shifted, omega, nu) - element_base) / x_step;
    shifted(k) = x(k);
    (*jacobian)(q_, k) = length * g_k.real();
    (*jacobian)(q_ + 1, k) = length * g_k.imag();
  }
  const double omega_step = pencil_step(std::abs(omega));
  const Complex g_omega = -(pencil_product(x, omega + omega_step, nu) - base) / omega_step;
  (*jacobian)(q_, q_) = length * g_nu.real();
  (*jacobian)(q_ + 1, q_) = length * g_nu.imag();
  (*jacobian)(q_, q_ + 1) = length * g_omega.real();
  (*jacobian)(q_ + 1, q_ + 1) = length * g_omega.imag();
  if (!r_gamma) return;
  r_gamma->resize(size());
  r_gamma->head(q_) = e.r_gamma;
  Complex g_gamma = 0.0;
  if (!linear_in_parameter_) {  // the amplitude does not enter Hill's matrices
    const double step = pencil_step(std::abs(gamma) + scales_.parameter);
    hbm_.set_parameter(parameter_, gamma + step);
    g_gamma = -(pencil_product(x, omega, nu) - base) / step;
    hbm_.set_parameter(parameter_, gamma);
  }
  (*r_gamma)(q_) = length * g_gamma.real();
  (*r_gamma)(q_ + 1) = length * g_gamma.imag();
}

Complex CriticalExponentSystem::bordering_scalar(const VectorXd& u, double gamma) {
  VectorXd r;
  evaluate(u, gamma, r, nullptr, nullptr);
  return g_;
}

void CriticalExponentSystem::accepted(const VectorXd& u, double gamma) {
  // The continuation evaluates the Jacobian at the point it accepts last; recompute otherwise.
  if (!(has_left_ && last_u_.size() == u.size() && last_u_ == u && last_gamma_ == gamma)) {
    hbm_.set_parameter(parameter_, gamma);
    form_pencil(u.head(q_), u(q_ + 1), u(q_));
    solve_bordered(true);
  }
  c_ = v_.normalized();
  b_ = w_.normalized();
}

std::vector<VectorXd> CriticalExponentSystem::borders() const { return {b_.real(), b_.imag(), c_.real(), c_.imag()}; }

void CriticalExponentSystem::restore_borders(const std::vector<VectorXd>& borders) {
  const Eigen::Index n = static_cast<Eigen::Index>(dofs_) * hbm_.basis().coefficients();
  if (borders.size() != 4)
    throw std::invalid_argument("Hill-pencil system: the saved borders must be 4 vectors (b and c, real and imaginary parts)");
  for (const VectorXd& part : borders)
    if (part.size() != n)
      throw std::invalid_argument("Hill-pencil system: the saved borders do not fit its pencil of " + std::to_string(n));
  b_ = borders[0].cast<Complex>() + Complex(0, 1) * borders[1].cast<Complex>();
  c_ = borders[2].cast<Complex>() + Complex(0, 1) * borders[3].cast<Complex>();
  last_u_.resize(0);
  has_left_ = false;
}

VectorXd CriticalExponentSystem::unknown_scale(const VectorXd& u) const {
  VectorXd s = FoldSystem::unknown_scale(u);
  s(q_) = scales_.omega;  // nu, a frequency
  return s;
}

std::vector<double> CriticalExponentSystem::resonance_tests(const VectorXd& u) const {
  const double phase = kPi * u(q_) / hbm_.fundamental(u(q_ + 1));
  return {std::sin(phase), std::cos(phase)};
}

double CriticalExponentSystem::critical_frequency(const VectorXd& u) const { return std::abs(u(q_)); }

}  // namespace hbtrack
