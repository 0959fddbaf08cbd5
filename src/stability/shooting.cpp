#include "hbtrack/stability/shooting.hpp"

#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hbtrack/timeint/equation_of_motion.hpp"
#include "hbtrack/util/dense_eigen.hpp"
#include "hbtrack/timeint/initial_state.hpp"

namespace hbtrack {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// One period of z' = F(t, z) (RK4) and of its variational equation Phi' = A(t) Phi, Phi(0) = I.
// A C0 law makes A(t) jump where the state crosses a switching surface: a fixed-step scheme
// straddling the jump is only first-order accurate in Phi (RK4 at 2000 steps put a multiplier
// of NLvib's two-dof example 0.15 off). So every step that crosses a surface is cut at the
// crossing (located on the step's cubic Hermite interpolant), and Phi advances by the
// fourth-order Magnus expansion, whose two Gauss points lie inside the step: A is then only
// sampled on one side of every jump. The state itself is C1 across a C0 law's corner.
class PeriodFlow {
 public:
  // `periods` forcing periods: nu for a solution of period nu 2 pi / omega (a subharmonic basis).
  PeriodFlow(EquationOfMotion& equation, int periods) : eq_(equation), n_(equation.dofs()), periods_(periods) {
    mass_inverse_ = equation.mass().llt().solve(MatrixXd::Identity(n_, n_));
  }

  void run(const VectorXd& z0, int steps, VectorXd& z, MatrixXd& phi) {
    const double period = periods_ * eq_.period(), dt = period / steps;
    z = z0;
    phi = MatrixXd::Identity(2 * n_, 2 * n_);
    double t = 0;
    VectorXd f0 = field(t, z), z1, f1, g;
    switching(z, g);
    Eigen::VectorXd side = g.unaryExpr([](double value) { return value >= 0 ? 1.0 : -1.0; });
    while (t < period * (1 - 1e-14)) {
      double h = std::min(dt, period - t);
      z1 = rk4(t, z, h);
      f1 = field(t + h, z1);
      switching(z1, g);
      const int crossed = earliest_crossing(h, z, f0, z1, f1, g, side);
      if (crossed >= 0) {
        z1 = rk4(t, z, h);  // h now ends on the surface
        f1 = field(t + h, z1);
        side(crossed) = -side(crossed);
      }
      advance_variational(h, z, f0, z1, f1, phi);
      t += h;
      z = z1;
      f0 = f1;
    }
  }

 private:
  // z' = F(t, z) = [v; M^-1 (f_ext - C v - K x - f_nl)].
  VectorXd field(double t, const VectorXd& z) {
    const auto x = z.head(n_), v = z.tail(n_);
    eq_.external_force(t, force_);
    eq_.nonlinear_force(t, x, v, nonlinear_);
    VectorXd dz(2 * n_);
    dz.head(n_) = v;
    dz.tail(n_) = mass_inverse_ * (force_ - nonlinear_ - eq_.stiffness() * x - eq_.damping() * v);
    return dz;
  }
  // A(t, z) = [[0, I], [-M^-1 (K + df/dx), -M^-1 (C + df/dv)]].
  // (The time matters to history elements only, which shooting_floquet refuses.)
  // The last derivatives' A is kept: on a piecewise-linear law they repeat between switches.
  const MatrixXd& tangent(const VectorXd& z) {
    eq_.nonlinear_force(0.0, z.head(n_), z.tail(n_), nonlinear_, &dfdx_, &dfdv_);
    if (last_a_.size() > 0 && dfdx_ == last_dfdx_ && dfdv_ == last_dfdv_) return last_a_;
    last_dfdx_ = dfdx_;
    last_dfdv_ = dfdv_;
    last_a_ = MatrixXd::Zero(2 * n_, 2 * n_);
    last_a_.topRightCorner(n_, n_).setIdentity();
    last_a_.bottomLeftCorner(n_, n_) = -mass_inverse_ * (eq_.stiffness() + dfdx_);
    last_a_.bottomRightCorner(n_, n_) = -mass_inverse_ * (eq_.damping() + dfdv_);
    return last_a_;
  }
  void switching(const VectorXd& z, VectorXd& g) { eq_.switching_values(z.head(n_), z.tail(n_), g); }
  VectorXd rk4(double t, const VectorXd& z, double h) {
    const VectorXd k1 = field(t, z);
    const VectorXd k2 = field(t + 0.5 * h, z + 0.5 * h * k1);
    const VectorXd k3 = field(t + 0.5 * h, z + 0.5 * h * k2);
    const VectorXd k4 = field(t + h, z + h * k3);
    return z + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  // The state at fraction s of a step of length h, from its ends and slopes (cubic Hermite).
  static VectorXd hermite(double s, double h, const VectorXd& z0, const VectorXd& f0, const VectorXd& z1, const VectorXd& f1) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * z0 + (s3 - 2 * s2 + s) * h * f0 + (-2 * s3 + 3 * s2) * z1 + (s3 - s2) * h * f1;
  }
  // The surface the step crosses first (-1: none); h is cut to end on it.
  int earliest_crossing(double& h, const VectorXd& z0, const VectorXd& f0, const VectorXd& z1, const VectorXd& f1, const VectorXd& g1,
                        const VectorXd& side) {
    int first = -1;
    double first_s = 1.0;
    VectorXd g;
    for (Eigen::Index i = 0; i < g1.size(); ++i) {
      if (g1(i) * side(i) >= 0) continue;
      // Illinois false position on s in [0, 1] for g_i(hermite(s)) = 0.
      double a = 0, b = 1, ga = side(i) * 1e-300, gb = g1(i);
      switching(z0, g);
      ga = g(i) == 0 ? ga : g(i);
      int retained = 0;
      for (int iteration = 0; iteration < 100 && b - a > 1e-14; ++iteration) {
        const double s = (a * gb - b * ga) / (gb - ga);
        switching(hermite(s, h, z0, f0, z1, f1), g);
        const double gs = g(i);
        if (gs * ga > 0) {
          a = s, ga = gs;
          if (retained == -1) gb *= 0.5;
          retained = -1;
        } else {
          b = s, gb = gs;
          if (retained == 1) ga *= 0.5;
          retained = 1;
        }
      }
      if (b < first_s) first_s = b, first = static_cast<int>(i);
    }
    if (first >= 0) h *= first_s;
    return first;
  }
  // Phi <- exp(Omega) Phi, Omega = h/2 (A1 + A2) + sqrt(3) h^2 / 12 [A2, A1] (Magnus, order 4).
  void advance_variational(double h, const VectorXd& z0, const VectorXd& f0, const VectorXd& z1, const VectorXd& f1, MatrixXd& phi) {
    const double c = std::sqrt(3.0) / 6.0;
    const MatrixXd a1 = tangent(hermite(0.5 - c, h, z0, f0, z1, f1));
    const MatrixXd& a2 = tangent(hermite(0.5 + c, h, z0, f0, z1, f1));
    // Equal A at both Gauss points (A constant over the step) commute: the commutator is zero.
    const MatrixXd omega =
        a1 == a2 ? MatrixXd(0.5 * h * (a1 + a2)) : MatrixXd(0.5 * h * (a1 + a2) + std::sqrt(3.0) * h * h / 12.0 * (a2 * a1 - a1 * a2));
    // A piecewise-linear law (a penalty spring, a gap) leaves A(t) constant between switches, so
    // at a fixed step most steps repeat the last step's Omega exactly: its exponential, the
    // step's main cost (a Pade approximant with scaling and squaring), is then reused as is.
    if (!(omega.size() == last_omega_.size() && omega == last_omega_)) {
      last_omega_ = omega;
      last_exponential_ = omega.exp();
    }
    phi = last_exponential_ * phi;
  }

  EquationOfMotion& eq_;
  int n_;
  int periods_;
  MatrixXd mass_inverse_, dfdx_, dfdv_;
  MatrixXd last_dfdx_, last_dfdv_, last_a_;  // the last derivatives tangent() saw and their A
  MatrixXd last_omega_, last_exponential_;   // the last step's Magnus exponent and its exponential
  VectorXd force_, nonlinear_;
};

}  // namespace

FloquetResult shooting_floquet(HarmonicBalance& hbm, const VectorXd& x, double omega, int steps, ShootingOutcome* outcome) {
  EquationOfMotion equation(hbm.model(), hbm.elements(), hbm.parameters(), omega);
  // The shooting state is (x, v): the sliders' positions of history elements would have to join
  // it, and their periodicity be solved for. The monodromy matrix carries them instead.
  if (equation.history_size() > 0) throw std::invalid_argument("shooting: history elements (friction sliders) are not supported");
  const int n = equation.dofs();
  // The basis' harmonics are multiples of the fundamental omega / nu, the orbit's period nu T.
  const MotionState start = state_from_harmonics(hbm.expand(x, omega), n, hbm.basis().harmonics(), hbm.fundamental(omega));
  VectorXd z0(2 * n);
  z0 << start.x, start.v;
  // Velocities weigh as omega * displacement, so that the test is a relative one on both.
  VectorXd weights(2 * n);
  weights << VectorXd::Ones(n), VectorXd::Constant(n, 1.0 / omega);
  const double scale = std::max(z0.cwiseProduct(weights).lpNorm<Eigen::Infinity>(), 1e-300);
  // The HBM orbit is off by its truncation error (1e-3 relative on a C0 law at H ~ 20); Newton
  // converges quadratically from there where the law is smooth, linearly across its corners.
  constexpr int kMaxIterations = 12;
  constexpr double kTolerance = 1e-9;

  PeriodFlow flow(equation, hbm.subharmonic());
  ShootingOutcome result;
  VectorXd z;
  MatrixXd phi;
  for (int iteration = 0;; ++iteration) {
    flow.run(z0, steps, z, phi);
    const VectorXd gap = z - z0;
    result.periodicity_error = gap.cwiseProduct(weights).lpNorm<Eigen::Infinity>() / scale;
    if (!gap.allFinite()) break;
    if (result.periodicity_error <= kTolerance) {
      result.converged = true;
      break;
    }
    if (iteration == kMaxIterations) break;
    const MatrixXd jacobian = phi - MatrixXd::Identity(2 * n, 2 * n);
    z0 -= jacobian.partialPivLu().solve(gap);
    ++result.newton_iterations;
  }
  result.state = z0;
  if (outcome) *outcome = result;

  FloquetResult r;
  r.method = StabilityMethod::shooting;
  const double period = hbm.subharmonic() * equation.period();
  const Eigen::VectorXcd mu =
      phi.allFinite() ? dense_eigenvalues(phi) : Eigen::VectorXcd::Constant(2 * n, std::complex<double>(INFINITY, 0));
  r.exponents = mu.array().log() / period;
  finish_floquet(r, hbm.fundamental(omega), 1e-9 * omega);
  r.multipliers = mu;
  return r;
}

}  // namespace hbtrack
