#include "hbtrack/analysis/torus_branch.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>
#include <tuple>
#include <string>

#include "hbtrack/analysis/critical_exponent_system.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Eigen::VectorXd;
using Complex = std::complex<double>;

namespace {

int power_of_two_above(int n) {
  int p = 1;
  while (p <= n) p *= 2;
  return p;
}

// The periodic solution (dense coefficients `full`, n(2H+1), a0/2 the mean) on the grid of `basis`.
MatrixXd periodic_samples(const VectorXd& full, int n, const TorusBasis& basis) {
  const int harmonics = static_cast<int>(full.size()) / n / 2;
  MatrixXd out(basis.grid(), n);
  for (int g = 0; g < basis.grid(); ++g) {
    const double t = basis.theta1(g);
    for (int d = 0; d < n; ++d) {
      double value = 0.5 * full(d);
      for (int k = 1; k <= harmonics; ++k) value += full((2 * k - 1) * n + d) * std::cos(k * t) + full(2 * k * n + d) * std::sin(k * t);
      out(g, d) = value;
    }
  }
  return out;
}

// Re(e^{i theta2} v(theta1)) on the grid, v in the Hill layout (coefficient c of `periodic`, entry c n + dof).
MatrixXd eigenvector_samples(const VectorXcd& v, int n, const FourierBasis& periodic, const TorusBasis& basis) {
  MatrixXd out = MatrixXd::Zero(basis.grid(), n);
  for (int g = 0; g < basis.grid(); ++g) {
    const double t1 = basis.theta1(g);
    const Complex turn = std::polar(1.0, basis.theta2(g));
    for (int c = 0; c < periodic.coefficients(); ++c) {
      const int k = periodic.harmonic_of(c);
      const double shape = k == 0 ? 0.5 : periodic.is_sine(c) ? std::sin(k * t1) : std::cos(k * t1);
      for (int d = 0; d < n; ++d) out(g, d) += (turn * v(c * n + d)).real() * shape;
    }
  }
  return out;
}

// The columns of `samples` (grid x model dofs) that the torus keeps, in its column order.
MatrixXd retained_columns(const MatrixXd& samples, const TorusSystem& system) {
  MatrixXd out(samples.rows(), system.dofs());
  for (int column = 0; column < system.dofs(); ++column) out.col(column) = samples.col(system.retained()[static_cast<size_t>(column)]);
  return out;
}

// x(theta1, theta2) of one dof (its coefficients in the basis' layout), its gradient and Hessian.
struct TorusValue {
  double x = 0, g1 = 0, g2 = 0, h11 = 0, h12 = 0, h22 = 0;
};
TorusValue torus_value(const TorusBasis& basis, const VectorXd& coefficients, double t1, double t2) {
  TorusValue v;
  v.x = coefficients(0);
  for (int p = 1; p < basis.pairs(); ++p) {
    const auto [k1, k2] = basis.pair(p);
    const double a = coefficients(TorusBasis::cosine(p)), b = coefficients(TorusBasis::sine(p));
    const double phase = k1 * t1 + k2 * t2, c = std::cos(phase), s = std::sin(phase);
    const double level = a * c + b * s, slope = b * c - a * s;
    v.x += level;
    v.g1 += k1 * slope, v.g2 += k2 * slope;
    v.h11 -= k1 * k1 * level, v.h12 -= k1 * k2 * level, v.h22 -= k2 * k2 * level;
  }
  return v;
}

// The largest value of sign * x(theta1, theta2) for one dof: the grid's extreme sample, then
// Newton on the gradient in the two phases (a sampled extreme is short of the true one by about
// (grid step)^2 / 2 relative). Where the Hessian is not definite of the right sign (a torus of
// zero size depends on theta1 alone) the step is taken along each phase whose curvature has it;
// a step that does not improve the value is halved.
double refined_extreme(const TorusBasis& basis, const VectorXd& coefficients, const VectorXd& grid_values, double sign) {
  Eigen::Index best = 0;
  (sign * grid_values).maxCoeff(&best);
  double t1 = basis.theta1(static_cast<int>(best)), t2 = basis.theta2(static_cast<int>(best));
  TorusValue v = torus_value(basis, coefficients, t1, t2);
  for (int it = 0; it < 20; ++it) {
    double d1 = 0, d2 = 0;
    const double det = v.h11 * v.h22 - v.h12 * v.h12;
    if (sign * v.h11 < 0 && sign * v.h22 < 0 && det > 0) {
      d1 = -(v.h22 * v.g1 - v.h12 * v.g2) / det;
      d2 = -(v.h11 * v.g2 - v.h12 * v.g1) / det;
    } else {
      if (sign * v.h11 < 0) d1 = -v.g1 / v.h11;
      if (sign * v.h22 < 0) d2 = -v.g2 / v.h22;
    }
    if (std::abs(d1) + std::abs(d2) < 1e-13) break;
    bool improved = false;
    for (int halving = 0; halving < 20 && !improved; ++halving, d1 *= 0.5, d2 *= 0.5) {
      const TorusValue trial = torus_value(basis, coefficients, t1 + d1, t2 + d2);
      if (sign * trial.x >= sign * v.x) {
        t1 += d1, t2 += d2, v = trial;
        improved = true;
      }
    }
    if (!improved) break;
  }
  return v.x;
}

std::vector<TorusEnvelope> envelope_of(const TorusSystem& system, const VectorXd& u, const std::vector<OutputDof>& outputs) {
  const MatrixXd grid = system.samples(u, system.basis());
  const Eigen::Map<const MatrixXd> x(u.data(), system.dofs(), system.basis().coefficients());
  std::vector<TorusEnvelope> out;
  for (const OutputDof& o : outputs) {
    const int column = system.column(o.dof);
    const VectorXd coefficients = x.row(column).transpose(), values = grid.col(column);
    out.push_back(
        {refined_extreme(system.basis(), coefficients, values, 1.0), refined_extreme(system.basis(), coefficients, values, -1.0)});
  }
  return out;
}

// Newton on the torus with its size fixed at `size` and omega free: [R; size - eps] = 0.
int solve_fixed_size(TorusSystem& system, VectorXd& u, double& omega, double size, const ContinuationOptions& o, double force,
                     double length) {
  const int m = system.size(), ia = system.index(TorusBasis::cosine(system.phase_pair()), system.phase_dof());
  VectorXd r, r_omega;
  MatrixXd j;
  for (int it = 0; it <= 2 * o.max_iterations; ++it) {
    system.evaluate(u, omega, r, &j, &r_omega);
    const double size_residual = force / length * (u(ia) - size);
    if (std::max(r.cwiseAbs().maxCoeff(), std::abs(size_residual)) <= o.tolerance * force) return it;
    MatrixXd a = MatrixXd::Zero(m + 1, m + 1);
    a.topLeftCorner(m, m) = j;
    a.topRightCorner(m, 1) = r_omega;
    a(m, ia) = force / length;
    VectorXd rhs(m + 1);
    rhs << -r, -size_residual;
    const VectorXd step = a.partialPivLu().solve(rhs);
    if (!step.allFinite()) break;
    u += step.head(m);
    omega += step(m);
  }
  return -1;
}

}  // namespace

bool TorusBranchResult::success() const {
  return stop_reason == StopReason::reached_end || stop_reason == StopReason::left_range || stop_reason == StopReason::reached_ns_point ||
         stop_reason == StopReason::max_points;
}

std::vector<int> torus_retained_dofs(const HarmonicBalance& hbm, const std::vector<OutputDof>& outputs) {
  std::vector<char> kept(static_cast<size_t>(hbm.model().dofs()), 0);
  for (const auto& element : hbm.elements())
    for (const int d : element->dofs) kept[static_cast<size_t>(d)] = 1;
  for (const OutputDof& o : outputs) kept[static_cast<size_t>(o.dof)] = 1;
  std::vector<int> retained;
  for (int d = 0; d < hbm.model().dofs(); ++d)
    if (kept[static_cast<size_t>(d)]) retained.push_back(d);
  return retained;
}

TorusOptions resolved_torus_options(const HarmonicBalance& hbm, TorusOptions o) {
  if (o.h1 == 0) o.h1 = hbm.options().harmonics;
  if (o.n1 == 0) o.n1 = std::max(hbm.options().effective_samples(), power_of_two_above(4 * o.h1));
  if (o.n2 == 0) o.n2 = power_of_two_above(4 * o.h2);  // alias-free for cubic laws: N > 4 H
  return o;
}

TorusBranchResult torus_branch(const HarmonicBalance& hbm, const VectorXd& x_ns, double omega_ns, const FoldScales& scales,
                               const TorusOptions& options, const std::vector<OutputDof>& outputs, const TorusObserver& observer) {
  const TorusOptions o = resolved_torus_options(hbm, options);
  TorusSystem system(hbm, TorusBasis(o.h1, o.h2, o.n1, o.n2), scales, torus_retained_dofs(hbm, outputs));
  const int n = system.dofs(), m = system.harmonic_unknowns();

  // The NS point on its defining system at these parameters, and Hill's eigenvector there.
  const int amplitude = hbm.amplitude_parameter();
  const double gamma = hbm.parameter_values()[static_cast<size_t>(amplitude)];
  CriticalExponentSystem ns(hbm, amplitude, scales, CriticalExponent::neimark_sacker);
  VectorXd z = ns.start_at(x_ns, omega_ns, gamma);
  if (newton_at_fixed_parameter(ns, z, gamma, o.continuation.tolerance, o.continuation.max_iterations) < 0)
    throw std::runtime_error("torus: the Neimark-Sacker point near omega = " + std::to_string(omega_ns) +
                             " could not be refined on its defining system");
  ns.accepted(z, gamma);
  const int q = hbm.unknowns();
  TorusBranchResult result;
  result.omega_ns = z(q + 1);
  result.nu = std::abs(z(q));
  const std::vector<VectorXd> borders = ns.borders();
  VectorXcd v = borders[2].cast<Complex>() + Complex(0, 1) * borders[3].cast<Complex>();
  if (z(q) < 0) v = v.conjugate();  // Re(e^{-i |nu| t} v) = Re(e^{i |nu| t} conj(v))

  HarmonicBalance evaluator(hbm);
  const int model_dofs = hbm.model().dofs();
  const VectorXd full = evaluator.expand(z.head(q), result.omega_ns);
  const MatrixXd periodic = retained_columns(periodic_samples(full, model_dofs, system.basis()), system);
  VectorXd u_periodic(system.size());
  u_periodic << system.project(periodic), result.nu;
  // Hill's pencil (CriticalExponentSystem) is on every dof of the model, condensed balance or not.
  const auto shape_of = [&](const VectorXcd& vector) {
    return system.project(retained_columns(eigenvector_samples(vector, model_dofs, hbm.basis(), system.basis()), system));
  };
  VectorXd shape = shape_of(v);

  // The phase pair: where the eigenvector is largest; v turned so that its sine coefficient is 0.
  double largest = -1;
  int phase_column = 0;
  for (int p = 1; p < system.basis().pairs(); ++p) {
    if (system.basis().pair(p).second == 0) continue;
    for (int d = 0; d < n; ++d) {
      const double size = std::hypot(shape(system.index(TorusBasis::cosine(p), d)), shape(system.index(TorusBasis::sine(p), d)));
      if (size > largest) largest = size, result.phase_pair = p, phase_column = d;
    }
  }
  if (!(largest > 0)) throw std::runtime_error("torus: Hill's eigenvector at the NS point has no (k1, +-1) content");
  system.set_phase_condition(result.phase_pair, phase_column);
  result.phase_dof = system.retained()[static_cast<size_t>(phase_column)];
  std::tie(result.k1, result.k2) = system.basis().pair(result.phase_pair);
  const double psi = std::atan2(shape(system.index(TorusBasis::sine(result.phase_pair), phase_column)),
                                shape(system.index(TorusBasis::cosine(result.phase_pair), phase_column)));
  v *= std::polar(1.0 / largest, psi / result.k2);
  shape = shape_of(v);

  TorusPoint ns_row;
  ns_row.omega = result.omega_ns;
  ns_row.omega2 = result.nu;
  ns_row.u = u_periodic;
  ns_row.envelope = envelope_of(system, u_periodic, outputs);
  result.points.push_back(ns_row);
  if (observer && !observer(ns_row, 0)) {
    result.stop_reason = StopReason::interrupted;
    return result;
  }

  // The first torus: its size fixed at eps, omega free.
  const double eps = o.start_fraction * periodic.col(phase_column).cwiseAbs().maxCoeff();
  VectorXd u = u_periodic;
  u.head(m) += eps * shape.head(m);
  double omega = result.omega_ns;
  if (solve_fixed_size(system, u, omega, eps, o.continuation, scales.force, scales.length) < 0)
    throw std::runtime_error("torus: no torus of size " + std::to_string(eps) + " next to the NS point at omega = " +
                             std::to_string(result.omega_ns) + " (Newton with omega free did not converge)");
  if (!(o.omega_min <= omega && omega <= o.omega_max))
    throw std::runtime_error("torus: the first torus is at omega = " + std::to_string(omega) + ", outside the range");

  ParameterWindow window{o.omega_min, o.omega_max, omega >= result.omega_ns ? 1 : -1, false};
  const double first_sign = system.torus_size(u) >= 0 ? 1.0 : -1.0;
  bool shrank = false;
  const ContinuationResult r = continue_within(system, u, omega, window, o.continuation, [&](const BranchPoint& b, int) {
    const double size = system.torus_size(b.u);
    if (size * first_sign <= 0) {
      shrank = true;
      return false;
    }
    TorusPoint p;
    p.omega = b.lambda;
    p.omega2 = b.u(m);
    p.size = size;
    p.u = b.u;
    p.newton_iterations = b.newton_iterations;
    p.envelope = envelope_of(system, b.u, outputs);
    result.points.push_back(p);
    return !observer || observer(p, static_cast<int>(result.points.size()) - 1);
  });
  result.summary = r.summary;
  result.special_points = r.special_points;
  result.stop_reason = shrank ? StopReason::reached_ns_point : r.summary.stop_reason;
  return result;
}

}  // namespace hbtrack
