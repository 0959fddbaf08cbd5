#pragma once
// Shared fixtures for the numerical tests: small models with every element type, and
// finite-difference derivatives.
#include <Eigen/Dense>
#include <cstdlib>
#include <functional>
#include <string>

#include "hbtrack/elements/scalar_elements.hpp"
#include "hbtrack/elements/tip_contact.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack::test {

// Appended, not `std::string(DIR) + "/" + relative`: GCC 12 reports a false -Warray-bounds on
// that chain at -O3.
inline std::string source_path(const std::string& relative) {
  std::string path(HBTRACK_SOURCE_DIR);
  path += '/';
  path += relative;
  return path;
}

// True in the AddressSanitizer/UndefinedBehaviorSanitizer build. The few tests that integrate or
// continue the full blade for minutes skip themselves there: the Release pass runs them, and the
// same code paths run under the sanitizers on the small models of the other tests.
constexpr bool kSanitizedBuild =
#ifdef HBTRACK_SANITIZED_BUILD
    true;
#else
    false;
#endif

// Central-difference derivative of a vector function along one scalar.
inline Eigen::VectorXd central_difference(const std::function<Eigen::VectorXd(double)>& f, double at, double h) {
  return (f(at + h) - f(at - h)) / (2.0 * h);
}

// Central-difference Jacobian of r(x).
inline Eigen::MatrixXd fd_jacobian(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& r, const Eigen::VectorXd& x, double h) {
  const Eigen::VectorXd r0 = r(x);
  Eigen::MatrixXd j(r0.size(), x.size());
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    Eigen::VectorXd xp = x, xm = x;
    xp(c) += h;
    xm(c) -= h;
    j.col(c) = (r(xp) - r(xm)) / (2.0 * h);
  }
  return j;
}

// Central differences of R(x, omega) in omega, and in parameter p (restored afterwards).
inline Eigen::VectorXd omega_difference(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, double h) {
  return central_difference(
      [&](double w) {
        Eigen::VectorXd r;
        hbm.evaluate(x, w, r);
        return r;
      },
      omega, h);
}
inline Eigen::VectorXd parameter_difference(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int p, double h) {
  const double p0 = hbm.parameters().value(p);
  const Eigen::VectorXd out = central_difference(
      [&](double value) {
        hbm.set_parameter(p, value);
        Eigen::VectorXd r;
        hbm.evaluate(x, omega, r);
        return r;
      },
      p0, h);
  hbm.set_parameter(p, p0);
  return out;
}

// max |a - b| relative to max |b| (or 1 when b is tiny).
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1e-300);
}

// n unit masses in a chain between two walls (unit springs to both walls and between the
// masses, dofs x1..xn), damping 0.02 K, a unit cosine force on dof `forced`.
inline StructuralModel chain_between_walls(int n, int forced) {
  StructuralModel m;
  for (int i = 1; i <= n; ++i) {
    std::string name(1, 'x');  // appended, as in source_path: GCC 12 warns falsely on "x" + ...
    name += std::to_string(i);
    m.dof_names.push_back(name);
  }
  m.mass = Eigen::MatrixXd::Identity(n, n);
  m.stiffness = 2.0 * Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i + 1 < n; ++i) m.stiffness(i, i + 1) = m.stiffness(i + 1, i) = -1.0;
  m.damping = 0.02 * m.stiffness;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(n);
  force(forced) = 1.0;
  m.forcing.push_back({1, force, Eigen::VectorXd::Zero(n)});
  return m;
}

// relative_error of the harmonic-balance Jacobian at (x, omega) against central differences of
// the residual with step h.
inline double residual_jacobian_error(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, double h) {
  Eigen::VectorXd r;
  Eigen::MatrixXd jacobian;
  hbm.evaluate(x, omega, r, &jacobian, nullptr);
  const auto residual = [&](const Eigen::VectorXd& y) {
    Eigen::VectorXd ry;
    hbm.evaluate(y, omega, ry, nullptr, nullptr);
    return ry;
  };
  return relative_error(jacobian, fd_jacobian(residual, x, h));
}

// Central differences (N x k) of an element's forces at the samples x (velocities v, frequency
// omega) with respect to its property p, with step h.
inline Eigen::MatrixXd property_difference(const NonlinearElement& e, const Eigen::MatrixXd& x, const Eigen::MatrixXd& v,
                                           const std::vector<double>& props, size_t p, double h, double omega = 1.0) {
  std::vector<double> plus = props, minus = props;
  plus[p] += h;
  minus[p] -= h;
  ElementResponse rp, rm;
  e.evaluate(x, v, omega, plus, rp, false);
  e.evaluate(x, v, omega, minus, rm, false);
  return (rp.force - rm.force) / (2 * h);
}

// Central differences of a history element's forces over a period with respect to each sample
// of each dof, in the layout of history_sensitivity_matrix: entry (t + N i, s + N j) is
// d f_i(t) / d x_j(s), with step h.
inline Eigen::MatrixXd history_difference(const NonlinearElement& e, const Eigen::MatrixXd& x, const std::vector<double>& props, double h) {
  const Eigen::Index n = x.rows(), k = x.cols();
  Eigen::MatrixXd fd(n * k, n * k);
  for (Eigen::Index j = 0; j < k; ++j)
    for (Eigen::Index s = 0; s < n; ++s) {
      Eigen::MatrixXd xp = x, xm = x;
      xp(s, j) += h, xm(s, j) -= h;
      ElementResponse rp, rm;
      e.evaluate(xp, xp, 1.0, props, rp, false);
      e.evaluate(xm, xm, 1.0, props, rm, false);
      const Eigen::MatrixXd column = (rp.force - rm.force) / (2 * h);
      for (Eigen::Index i = 0; i < k; ++i) fd.block(i * n, j * n + s, n, 1) = column.col(i);
    }
  return fd;
}

// A 9-dof model: a 3-dof tip node [r, t, z] in contact with a casing (polynomial law, Lanczos,
// friction), a cubic spring between dofs 3 and 4, tanh friction on dof 5, and three linear dofs
// (6-8) that condensation eliminates.
// `general_damping` makes C non-proportional (Schur condensation only).
struct ContactFixture {
  StructuralModel model;
  ElementList elements;
  ParameterSet parameters;
  int mu = -1, clearance = -1;
};

inline ContactFixture contact_fixture(bool general_damping, double lanczos) {
  ContactFixture f;
  const int n = 9;
  for (int i = 0; i < n; ++i)
    f.model.dof_names.push_back(std::string(1, 'd') += std::to_string(i));  // not "d" + ...: GCC 12 -Wrestrict false positive
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i + 1 < n; ++i) a(i, i + 1) = a(i + 1, i) = 0.2;
  f.model.mass = a;
  Eigen::MatrixXd k = 4.0 * Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i + 1 < n; ++i) k(i, i + 1) = k(i + 1, i) = -1.0;
  k(0, 3) = k(3, 0) = -0.5;
  k(1, 8) = k(8, 1) = -0.7;
  f.model.stiffness = k;
  f.model.damping = 0.01 * k + 0.02 * a;
  if (general_damping) {
    f.model.damping(1, 4) = f.model.damping(4, 1) = 0.03;
    f.model.damping(2, 7) = f.model.damping(7, 2) = 0.02;
  }
  HarmonicForce h1{1, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  h1.cos_part << 0.5, 0.1, 0.0, 0.2, 0.0, 0.1, 0.3, 0.0, 0.2;
  h1.sin_part << 0.0, 0.0, 0.1, 0.0, 0.3, 0.0, 0.0, 0.2, 0.0;
  HarmonicForce h2{2, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  h2.cos_part(3) = 0.05;
  f.model.forcing = {h1, h2};
  f.parameters.set("amplitude", 1.3);
  f.mu = f.parameters.set("mu", 0.15);
  f.clearance = f.parameters.set("clearance", 0.02);

  auto tip = std::make_shared<TipContact>(ContactLawKind::polynomial);
  tip->dofs = {0, 1, 2};
  tip->properties = {ParameterBinding::constant(50.0), ParameterBinding::linked(f.clearance), ParameterBinding::constant(0.3),
                     ParameterBinding::linked(f.mu),   ParameterBinding::constant(0.4),       ParameterBinding::constant(1.0),
                     ParameterBinding::constant(0.2)};
  tip->lanczos_exponent = lanczos;
  auto cubic = std::make_shared<CubicSpring>();
  cubic->dofs = {3, 4};
  cubic->weights = (Eigen::VectorXd(2) << 1.0, -1.0).finished();
  cubic->properties = {ParameterBinding::constant(2.0)};
  auto friction = std::make_shared<TanhFriction>();
  friction->dofs = {5};
  friction->weights = Eigen::VectorXd::Ones(1);
  friction->properties = {ParameterBinding::linked(f.mu, 2.0), ParameterBinding::constant(0.5), ParameterBinding::constant(0.05)};
  f.elements = {tip, cubic, friction};
  return f;
}

// The contact fixture (no general damping, Lanczos 1) at H = 3, 64 samples, and a state at
// omega = 1.3 where the tip's radial dof enters contact over part of the period: a point where
// the tracking systems' Jacobians see friction, Lanczos factors and a parameter inside a law.
struct ContactPoint {
  HarmonicBalance hbm;
  Eigen::VectorXd x;
  double omega = 1.3;
};

inline ContactPoint contact_point_in_contact() {
  ContactFixture f = contact_fixture(false, 1.0);
  HarmonicBalanceOptions o;
  o.harmonics = 3;
  o.samples = 64;
  ContactPoint p{HarmonicBalance(f.model, f.elements, f.parameters, o), {}, 1.3};
  std::srand(5);
  p.x = 0.01 * Eigen::VectorXd::Random(p.hbm.unknowns());
  const int q = p.hbm.retained_dofs();
  p.x(1 * q + 0) = 0.08;  // the tip's radial dof enters contact over part of the period
  p.x(2 * q + 1) = 0.05;
  return p;
}

}  // namespace hbtrack::test
