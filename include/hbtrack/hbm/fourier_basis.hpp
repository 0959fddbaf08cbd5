#pragma once
// Real Fourier basis sampled at N instants tau_i = 2 pi i / N (paper eqs 3, 17, 19), over a list
// of harmonic numbers (sorted, unique, >= 0; by default 0..H): [1/2 if 0 is listed, then
// cos(k tau), sin(k tau) for each listed k > 0]. Coefficient index c: with 0..H, 0 is a0, 2j-1
// is a_j, 2j is b_j; with a selection (e.g. 1, 3, 5) the pairs follow in the list's order.
// Harmonic vectors are ordered harmonic-major: entry c*q + dof (paper eq 5). H, the largest
// listed harmonic, sets the sampling and the "dense" layout 0..H that expanded solutions use.
#include <Eigen/Dense>
#include <vector>

namespace hbtrack {

class FourierBasis {
 public:
  FourierBasis(int harmonics, int samples);  // 0..H; throws std::invalid_argument unless H>=0, N>=2H+1
  // A selection: sorted, unique, >= 0, not empty; N >= 2 max + 1.
  FourierBasis(std::vector<int> harmonic_numbers, int samples);

  int harmonics() const { return harmonics_; }  // H, the largest harmonic
  int samples() const { return samples_; }
  int coefficients() const { return static_cast<int>(harmonic_of_.size()); }
  const std::vector<int>& harmonic_numbers() const { return numbers_; }
  bool has_mean() const { return !numbers_.empty() && numbers_.front() == 0; }
  // Whether the list is 0..H (the coefficient index then equals the dense one).
  bool dense() const { return coefficients() == 2 * harmonics_ + 1; }
  int harmonic_of(int c) const { return harmonic_of_[static_cast<size_t>(c)]; }
  bool is_sine(int c) const { return c > 0 && dense_index_[static_cast<size_t>(c)] % 2 == 0; }
  // Index in the dense layout 0..H of coefficient c (0 a0, 2k-1 a_k, 2k b_k).
  int dense_index(int c) const { return dense_index_[static_cast<size_t>(c)]; }
  // Coefficient index of cos(k tau) (a0 for k = 0), -1 when k is not listed.
  int cosine_index(int k) const;

  // Harmonic-major vectors of `dofs` blocks: selected layout <-> dense layout 0..H (zeros where
  // not listed; dropped when going back).
  Eigen::VectorXd to_dense(const Eigen::VectorXd& coeffs, int dofs) const;
  Eigen::VectorXd from_dense(const Eigen::VectorXd& dense, int dofs) const;

  // Gamma: N x nc, time samples = synthesis * coefficients.
  const Eigen::MatrixXd& synthesis() const { return synthesis_; }
  // Gamma * nabla: N x nc, samples of d/d(tau) (multiply by the fundamental frequency for d/dt).
  const Eigen::MatrixXd& derivative_synthesis() const { return derivative_synthesis_; }
  // Gamma^-1 = (2/N) [1; cos; sin; ...]: nc x N, coefficients = analysis * samples.
  const Eigen::MatrixXd& analysis() const { return analysis_; }
  // The dense projection up to order 2H, (4H+1) x N: the coefficients of a product g(t) x(t)
  // only need those of g up to 2H.
  const Eigen::MatrixXd& product_analysis() const { return product_analysis_; }

  // The nc x nc matrix Gamma^-1 diag(g) Gamma, built from the (4H+1) coefficients of g (layout of
  // product_analysis) by the product-to-sum identities: a Toeplitz-plus-Hankel structure, exact
  // for the sampled g whatever N.
  void product_matrix(const double* g_coeffs, Eigen::Ref<Eigen::MatrixXd> out) const;
  // out = in * nabla (right-multiplication by the derivative operator), in place allowed.
  void right_multiply_derivative(Eigen::Ref<Eigen::MatrixXd> m) const;
  // Coefficients of d/d(tau) of a signal: out(k) for harmonic-major vectors with q dofs.
  void derivative(const Eigen::VectorXd& coeffs, int dofs, Eigen::VectorXd& out) const;

 private:
  void build();
  int harmonics_;
  int samples_;
  std::vector<int> numbers_;
  std::vector<int> harmonic_of_, dense_index_;
  Eigen::MatrixXd synthesis_, derivative_synthesis_, analysis_, product_analysis_;
};

}  // namespace hbtrack
