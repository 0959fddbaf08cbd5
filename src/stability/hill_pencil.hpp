#pragma once
// Solves with Hill's quadratic pencil P(s) = J + s D1 + s^2 (I x M) at a real shift s, by
// block elimination: the model's linear part couples dofs only within one harmonic (the cosine
// and sine of harmonic j), so the dofs no element touches are eliminated harmonic by harmonic
// with small dense LUs, and only the Schur complement on the element dofs of every harmonic is
// factorised. On the blade (12 of 39 dofs linear, H = 10) that is an LU of 567 instead of 819.
// The pencil's entries come from the structured system (hill_system.hpp), never from dense
// n(2H+1) matrices.
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/util/dense_lu.hpp"
#include "hill_system.hpp"

namespace hbtrack {

class HillPencil {
 public:
  HillPencil(const HillSystem& system, double shift);
  // P(s)^-1 r, r of size n nc (harmonic-major over every dof).
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;

 private:
  struct Group {                                 // one harmonic: its coefficient blocks' linear-dof and coupled-dof positions
    std::vector<Eigen::Index> linear;            // in the full vector
    std::vector<Eigen::Index> coupled_in_schur;  // in the Schur unknowns (harmonic-major over the coupled dofs)
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;     // of P[linear, linear]
    Eigen::MatrixXd to_linear;                   // P[linear, coupled]
    Eigen::MatrixXd from_linear;                 // P[coupled, linear]
  };
  std::vector<Group> groups_;
  std::vector<Eigen::Index> schur_positions_;  // the full-vector position of each Schur unknown
  DenseLU schur_;                              // the one large factorization: the continuation's LU (OpenBLAS when built with it)
  Eigen::Index size_;
};

}  // namespace hbtrack
