#pragma once
// Real Fourier basis T_H = [1/2, cos(t), sin(t), ..., cos(Ht), sin(Ht)] sampled at N instants
// tau_i = 2 pi i / N (paper eqs 3, 17, 19). Coefficient index k: 0 is a0, 2j-1 is a_j, 2j is b_j.
// Harmonic vectors are ordered harmonic-major: entry k*q + dof (paper eq 5).
#include <Eigen/Dense>

namespace hbtrack {

class FourierBasis {
 public:
  FourierBasis(int harmonics, int samples);  // throws std::invalid_argument unless H>=0, N>=2H+1

  int harmonics() const { return harmonics_; }
  int samples() const { return samples_; }
  int coefficients() const { return 2 * harmonics_ + 1; }
  static int harmonic_of(int k) { return (k + 1) / 2; }

  // Gamma: N x (2H+1), time samples = synthesis * coefficients.
  const Eigen::MatrixXd& synthesis() const { return synthesis_; }
  // Gamma * nabla: N x (2H+1), samples of d/d(tau) (multiply by omega for d/dt).
  const Eigen::MatrixXd& derivative_synthesis() const { return derivative_synthesis_; }
  // Gamma^-1 = (2/N) [1; cos; sin; ...]: (2H+1) x N, coefficients = analysis * samples.
  const Eigen::MatrixXd& analysis() const { return analysis_; }
  // The same projection up to order 2H, (4H+1) x N: the coefficients of a product g(t) x(t)
  // only need those of g up to 2H.
  const Eigen::MatrixXd& product_analysis() const { return product_analysis_; }

  // The (2H+1) x (2H+1) matrix Gamma^-1 diag(g) Gamma, built from the (4H+1) coefficients of
  // g (layout of product_analysis) by the product-to-sum identities: a Toeplitz-plus-Hankel
  // structure, exact for the sampled g whatever N.
  void product_matrix(const double* g_coeffs, Eigen::Ref<Eigen::MatrixXd> out) const;
  // out = in * nabla (right-multiplication by the derivative operator), in place allowed.
  void right_multiply_derivative(Eigen::Ref<Eigen::MatrixXd> m) const;
  // Coefficients of d/d(tau) of a signal: out(k) for harmonic-major vectors with q dofs.
  void derivative(const Eigen::VectorXd& coeffs, int dofs, Eigen::VectorXd& out) const;

 private:
  int harmonics_;
  int samples_;
  Eigen::MatrixXd synthesis_, derivative_synthesis_, analysis_, product_analysis_;
};

}  // namespace hbtrack
