#pragma once
// The linear part of the harmonic balance system reduced, harmonic by harmonic, onto the
// retained (nonlinear) dofs: for harmonic j with complex amplitude z = a - i b,
//   R_j = Zr_j(omega) z + g_j - amplitude * Fr_j(omega),
// with Zr_j = Z_rr - Z_rl Z_ll^-1 Z_lr the Schur complement of Z_j = K - (j w)^2 M + i j w C and
// Fr_j the reduced unit forcing (method notes section 1). The linear dofs are recovered from z.
// A condenser is constant once built; what it computes at a frequency (the reduced operators and
// the factors they came from) lives in a CondensedOperators the caller owns, one per workspace.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "hbtrack/model/structural_model.hpp"

namespace hbtrack {

// The reduced operators at one frequency, per harmonic j, and the factors they came from (each
// condenser fills the ones it uses).
struct CondensedOperators {
  double omega = -1.0;  // where they were computed; -1: not yet
  std::vector<Eigen::MatrixXcd> reduced_stiffness;
  std::vector<Eigen::VectorXcd> reduced_force;
  // Schur: LU of Z_ll, Z_ll^-1 Z_lr and Z_ll^-1 F_l.
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXcd>> lu;
  std::vector<Eigen::MatrixXcd> coupling;
  std::vector<Eigen::VectorXcd> linear_response;
  // Modal: the receptance's diagonal and the retained dofs' unit forced response.
  std::vector<Eigen::VectorXcd> modal_receptance, retained_forced_response;
};

class LinearCondenser {
 public:
  virtual ~LinearCondenser() = default;
  virtual std::string method() const = 0;
  // Recomputes the reduced operators at omega into `at` (no-op if it holds them at omega).
  virtual void update(double omega, CondensedOperators& at) const = 0;
  // d/d(omega) of Zr_j z - amplitude Fr_j at fixed z, `at` updated to the frequency.
  virtual Eigen::VectorXcd omega_derivative(int j, const Eigen::VectorXcd& z, double amplitude, const CondensedOperators& at) const = 0;
  // Harmonic j of every dof (size n) given the retained dofs' harmonic z at a solution.
  virtual Eigen::VectorXcd recover(int j, const Eigen::VectorXcd& z, double amplitude, const CondensedOperators& at) const = 0;
  const std::vector<int>& retained() const { return retained_; }
  int harmonics() const { return harmonics_; }

 protected:
  std::vector<int> retained_;
  int harmonics_ = 0;
};

// Unit forcing of harmonic j as complex amplitudes (cos - i sin); order 0 gives a0 = 2 * value.
std::vector<Eigen::VectorXcd> complex_forcing(const StructuralModel& model, int harmonics);

// Direct Schur complement with a complex LU of Z_ll per harmonic. Works for any damping.
// With every dof retained it is the uncondensed (full) system.
std::unique_ptr<LinearCondenser> make_schur_condenser(const StructuralModel& model, std::vector<int> retained, int harmonics);
// Receptance from the undamped modes, Zr_j = (Phi_r D_j Phi_r^T)^-1: exact (all modes kept) and
// much cheaper for many linear dofs, valid when the modes diagonalise C.
std::unique_ptr<LinearCondenser> make_modal_condenser(const StructuralModel& model, std::vector<int> retained, int harmonics);
// True when the undamped modes diagonalise C (relative off-diagonal below 1e-10) and K > 0.
bool modes_diagonalise_damping(const StructuralModel& model);

}  // namespace hbtrack
