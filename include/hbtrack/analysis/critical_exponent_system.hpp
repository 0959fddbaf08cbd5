#pragma once
// Defining system of a Neimark-Sacker (NS) or period-doubling (PD) point of the harmonic balance
// solutions, as a continuation problem in a second parameter gamma, minimally augmented on Hill's
// quadratic pencil P(lambda) = J + lambda D1 + lambda^2 D2 (stability/hill_system.hpp).
//
// A Floquet exponent crosses the imaginary axis at lambda = i nu: P(i nu) is singular. With the
// complex bordered matrix [[A, b], [c^H, 0]], A = J + i nu D1 - nu^2 D2, and
// [[A, b], [c^H, 0]] [v; g] = [0; 1], g = 0 exactly when A is singular. Unknowns [x, nu, omega]
// (q + 2), equations R = 0, Re g = 0, Im g = 0. The borders follow v and the left vector w
// ([w; h] from the conjugate-transposed matrix) from point to point.
//
// A PD is the same system started at the exponent near i omega / 2: in the truncated Hill matrix
// the PD family's exponents sit a little off i omega / 2 (the truncation breaks the reflection
// lambda -> conj(lambda) + i omega), so P(i omega / 2) is never exactly singular and fixing
// nu = omega / 2 would ask two conditions of one unknown; with nu free the system asks of that
// exponent what the NFRC's test function asks (zero real part), and so passes through the NFRC's
// PD points (docs/tracking.md).
//
// Derivatives: g_z = -w^H A_z v. A_nu = i D1 - 2 nu D2 is exact; A_x, A_omega and A_gamma come
// from forward differences of the scalar w^H A v (step eta (|z| + eta), eta = 1e-6, as the fold
// systems), A_x from the elements' blocks alone (the linear part does not depend on x), one
// evaluation of them per unknown: they only shape Newton's Jacobian, the residual (the
// singularity itself) is exact.
#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_systems.hpp"

namespace hbtrack {

// Which exponent crossing a system follows.
enum class CriticalExponent { neimark_sacker, period_doubling };

class CriticalExponentSystem final : public FoldSystem {
 public:
  CriticalExponentSystem(const HarmonicBalance& hbm, int parameter, const FoldScales& scales, CriticalExponent kind);
  std::string method() const override { return "bordered"; }
  int size() const override { return q_ + 2; }
  void evaluate(const Eigen::VectorXd& u, double gamma, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_gamma) override;
  // Not used: the start needs the critical exponent (start_at finds it from Hill's exponents).
  Eigen::VectorXd start(const Eigen::VectorXd& x, double omega, const Eigen::VectorXd& right, const Eigen::VectorXd& left) override;
  // Unknowns at an NS (PD) point (x, omega) located at gamma: nu the imaginary part of Hill's
  // exponent there nearest the axis among the complex (PD: multiplier near -1) ones, borders
  // the approximate null vectors of P(i nu). Throws std::runtime_error without such an exponent.
  Eigen::VectorXd start_at(const Eigen::VectorXd& x, double omega, double gamma) override;
  // The same with the exponent's frequency nu given (a point interpolated on a curve: near a PD
  // the multipliers off the curve may be a complex pair, which start_at would not take).
  Eigen::VectorXd start_at_frequency(const Eigen::VectorXd& x, double omega, double gamma, double nu);
  void accepted(const Eigen::VectorXd& u, double gamma) override;
  std::vector<Eigen::VectorXd> borders() const override;
  void restore_borders(const std::vector<Eigen::VectorXd>& borders) override;
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override;
  // The crossing exponent's frequency |nu| (P(-i nu) is P(i nu) conjugated): the NS frequency,
  // in [0, w/2] (w the fundamental; a leg ends at either bound), the multiplier's angle 2 pi
  // |nu| / w. On a PD curve w/2 up to Hill's truncation, either side of it.
  double critical_frequency(const Eigen::VectorXd& u) const override;
  // sin(pi nu / w) and cos(pi nu / w): zero where the exponent's frequency reaches a multiple of
  // the fundamental w (a 1:1 resonance, multipliers at +1) or of w/2 past it (1:2, at -1).
  std::vector<double> resonance_tests(const Eigen::VectorXd& u) const;
  CriticalExponent kind() const { return kind_; }
  // The bordering scalar g at u (tests): zero at an NS (PD) point.
  std::complex<double> bordering_scalar(const Eigen::VectorXd& u, double gamma);

 private:
  using MatrixXcd = Eigen::MatrixXcd;
  using VectorXcd = Eigen::VectorXcd;
  // A = P(i nu) at (x, omega) with the current parameter values, into a_; J and D1 kept.
  void form_pencil(const Eigen::VectorXd& x, double omega, double nu);
  // w^H P(i nu) v from the Hill matrices at (x, omega): the scalar whose differences give g_z.
  std::complex<double> pencil_product(const Eigen::VectorXd& x, double omega, double nu);
  // Its elements' part alone, on the dofs they touch: all of it that depends on x, so its
  // differences in x are those of pencil_product without the linear part's cancellation, and
  // without forming the full Hill matrices once per unknown.
  std::complex<double> element_product(const Eigen::VectorXd& x, double omega, double nu);
  // v, w and g of the bordered system at the current a_.
  void solve_bordered(bool left);
  // D2 y = (I x M) y.
  VectorXcd mass_times(const VectorXcd& y) const;

  CriticalExponent kind_;
  int dofs_;  // n: Hill's matrices are over every model dof
  Eigen::MatrixXd hill_j_, hill_d1_;
  std::vector<int> coupled_;                // the model dofs the elements touch, ascending
  Eigen::MatrixXd element_j_, element_d1_;  // their blocks of J and D1 (hill_element_blocks)
  Eigen::VectorXcd coupled_v_, coupled_w_;  // v and w on those dofs, harmonic-major
  MatrixXcd a_, bordered_;
  Eigen::PartialPivLU<MatrixXcd> lu_;
  VectorXcd b_, c_, v_, w_;
  std::complex<double> g_;
  Eigen::VectorXd last_u_;
  double last_gamma_ = 0;
  bool has_left_ = false;
};

}  // namespace hbtrack
