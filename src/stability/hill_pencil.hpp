#pragma once
// Solves with Hill's quadratic pencil P(s) = J + s D1 + s^2 (I x M) at a real shift s, by
// block elimination: the model's linear part couples dofs only within one harmonic (the cosine
// and sine of harmonic j), so the dofs no element touches are eliminated harmonic by harmonic
// with small dense LUs, and only the Schur complement on the element dofs of every harmonic is
// factorised. On the blade (12 of 39 dofs linear, H = 10) that is an LU of 567 instead of 819.
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/util/dense_lu.hpp"

namespace hbtrack {

class HillPencil {
 public:
  // J and D1: n(2H+1) square, harmonic-major (block b = rows b*n .. b*n+n-1; blocks 2j-1 and
  // 2j are harmonic j); M: n x n; coupled: the dofs the nonlinear elements touch.
  HillPencil(const Eigen::MatrixXd& jacobian, const Eigen::MatrixXd& damping, const Eigen::MatrixXd& mass, double shift,
             const std::vector<int>& coupled);
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;

 private:
  struct Group {  // one harmonic: its linear-dof and coupled-dof positions
    std::vector<Eigen::Index> linear, coupled;
    std::vector<Eigen::Index> coupled_in_schur;  // positions of `coupled` in the Schur unknowns
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;     // of P[linear, linear]
    Eigen::MatrixXd to_linear;                   // P[linear, coupled]
    Eigen::MatrixXd from_linear;                 // P[coupled, linear]
  };
  std::vector<Group> groups_;
  std::vector<Eigen::Index> schur_positions_;  // every coupled position, group by group
  DenseLU schur_;  // the one large factorization: the continuation's LU (OpenBLAS when built with it)
  Eigen::Index size_;
};

}  // namespace hbtrack
