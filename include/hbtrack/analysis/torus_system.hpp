#pragma once
// The harmonic balance of a quasi-periodic response in two base frequencies (hyper-time AFT), on
// the retained dofs (the elements' and the outputs'; the other, linear dofs condensed out pair by
// pair, torus_linear_part.hpp):
//   M x'' + C x' + K x + f_nl(x, x') = amplitude g(omega) f(omega t),   x = x(omega t, omega2 t),
// x expanded in the TorusBasis (torus_basis.hpp). The linear part is balanced pair by pair at the
// frequency Omega = k1 omega + k2 omega2; the elements' forces are evaluated on the N1 x N2 grid of
// the two phases and projected back (the 2-D DFT), their Jacobian P diag(df/dx) E exactly.
// As a continuation problem in lambda = omega: unknowns u = [X, omega2], X harmonic-major
// (entry c n + column, c the TorusBasis coefficient, column the retained dof's position), n (2 P - 1) + 1 in all; equations the harmonic
// balance (n (2 P - 1)) and a phase condition that removes the free shift of theta2: the sine
// coefficient of one pair (k1, k2 != 0) of one dof is zero (set_phase_condition). Velocity- and
// omega-dependent laws are taken; history-dependent laws, laws that read the linear residual
// (DLFT), a Lanczos filter and subharmonic bases are refused (the constructor throws
// std::invalid_argument naming the element and the rule).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_systems.hpp"
#include "hbtrack/analysis/torus_linear_part.hpp"
#include "hbtrack/analysis/torus_basis.hpp"
#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack {

class TorusSystem final : public ContinuationProblem {
 public:
  // At the evaluator's parameter values; `scales`: length, force and frequency units (FoldScales).
  // `retained`: the model dofs kept as unknowns, every element's among them (empty: every dof).
  TorusSystem(const HarmonicBalance& hbm, TorusBasis basis, const FoldScales& scales, std::vector<int> retained = {});

  const TorusBasis& basis() const { return basis_; }
  // Retained dofs: their count, their model dofs in column order, the column of a model dof (-1: condensed out).
  int dofs() const { return dofs_; }
  const std::vector<int>& retained() const { return retained_; }
  int column(int model_dof) const { return column_of_[static_cast<size_t>(model_dof)]; }
  // Unknowns of the harmonic balance alone (n (2 P - 1)); omega2 is the last unknown.
  int harmonic_unknowns() const { return dofs_ * basis_.coefficients(); }
  int size() const override { return harmonic_unknowns() + 1; }
  // The coefficient of retained column `dof`, index c of the basis, within u.
  int index(int c, int dof) const { return c * dofs_ + dof; }
  // The phase condition: u(index(TorusBasis::sine(pair), dof)) = 0; pair has k2 != 0, dof a column.
  void set_phase_condition(int pair, int dof);
  int phase_pair() const { return phase_pair_; }
  int phase_dof() const { return phase_dof_; }
  // The cosine coefficient of the phase pair: the signed size of the torus in theta2 (zero on
  // the periodic branch, where the torus is born or closes).
  double torus_size(const Eigen::VectorXd& u) const { return u(index(TorusBasis::cosine(phase_pair_), phase_dof_)); }

  void evaluate(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_omega) override;
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override;
  double parameter_scale() const override { return scales_.omega; }
  double residual_scale() const override { return scales_.force; }

  // Displacements of the retained dofs over the grid of `grid_basis` (any TorusBasis with the
  // same pairs' harmonics H1, H2): grid x n.
  Eigen::MatrixXd samples(const Eigen::VectorXd& u, const TorusBasis& grid_basis) const;
  // Coefficients (u's harmonic layout, omega2 left out) of displacements given on this basis' grid.
  Eigen::VectorXd project(const Eigen::MatrixXd& grid_samples) const;

 private:
  void add_linear_part(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian,
                       Eigen::VectorXd* r_omega) const;
  void add_element_forces(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_omega);

  HarmonicBalance hbm_;
  TorusBasis basis_;
  FoldScales scales_;
  TorusLinearPart linear_;
  std::vector<int> retained_, column_of_;
  int dofs_ = 0;
  int phase_pair_ = -1, phase_dof_ = 0;
  // Buffers: samples of every dof (grid x n), of its velocity, an element's local ones.
  Eigen::MatrixXd x_samples_, v_samples_, velocity_synthesis_, local_x_, local_v_, weighted_, block_;
};

}  // namespace hbtrack
