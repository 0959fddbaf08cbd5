#pragma once
// The linear part of a torus' balance, pair by pair, reduced onto the retained dofs. For the pair
// at frequency Omega = k1 omega + k2 omega2 with complex coefficients z = a - i b on the retained
// dofs r, Z(Omega) = K - Omega^2 M + i Omega C is split over r and the condensed dofs l (those no
// element and no output reads), and
//   Zr = Z_rr - Z_rl Z_ll^-1 Z_lr,   Fr = F_r - Z_rl Z_ll^-1 F_l,   R = Zr z - level Fr,
// the Schur complement at that pair's own frequency: exact, as the periodic balance's condensation
// is harmonic by harmonic (hbm/linear_condenser.hpp), but at frequencies no harmonic list holds.
// dR/dOmega at fixed z is the condensation of dZ/dOmega applied to the whole response (z and the
// condensed dofs' z_l = Z_ll^-1 (level F_l - Z_lr z)): [dZ x]_r - Z_rl Z_ll^-1 [dZ x]_l.
// With every dof retained it is Z itself.
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/model/structural_model.hpp"

namespace hbtrack {

struct PairBalance {
  Eigen::VectorXcd residual;              // R (retained dofs)
  Eigen::MatrixXcd stiffness;             // Zr, when asked for
  Eigen::VectorXcd frequency_derivative;  // dR/dOmega at fixed z, when asked for
  Eigen::VectorXcd reduced_force;         // Fr of the unit forcing, when the pair is forced
};

class TorusLinearPart {
 public:
  // `retained`: model dofs, in the order of the torus' columns (unique, in range).
  TorusLinearPart(const StructuralModel& model, std::vector<int> retained);

  const std::vector<int>& retained() const { return retained_; }
  bool condenses() const { return !condensed_.empty(); }

  // The balance of one pair at `frequency` for coefficients z; `unit_force` (model dofs, complex
  // cos - i sin amplitudes; may be null) times `level` is its forcing.
  PairBalance balance(double frequency, const Eigen::VectorXcd& z, const Eigen::VectorXcd* unit_force, double level,
                      bool with_derivatives) const;

 private:
  std::vector<int> retained_, condensed_;
  // M, C, K split into the blocks rr, rl, lr, ll.
  struct Blocks {
    Eigen::MatrixXd rr, rl, lr, ll;
  };
  Blocks mass_, damping_, stiffness_;
  Eigen::VectorXcd part(const Eigen::VectorXcd& full, const std::vector<int>& dofs) const;
};

}  // namespace hbtrack
