#include "hill_pencil.hpp"

#include <algorithm>

namespace hbtrack {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

VectorXd gather(const VectorXd& v, const std::vector<Index>& at) {
  VectorXd out(static_cast<Index>(at.size()));
  for (size_t i = 0; i < at.size(); ++i) out(static_cast<Index>(i)) = v(at[i]);
  return out;
}

// The pencil's linear part over the blocks of one harmonic, rows x cols model dofs per block.
MatrixXd group_block(const HillSystem& system, const std::vector<int>& blocks, double shift, const std::vector<int>& rows,
                     const std::vector<int>& cols) {
  const Index nr = static_cast<Index>(rows.size()), nc = static_cast<Index>(cols.size());
  MatrixXd out(nr * static_cast<Index>(blocks.size()), nc * static_cast<Index>(blocks.size()));
  for (size_t i = 0; i < blocks.size(); ++i)
    for (size_t j = 0; j < blocks.size(); ++j)
      out.block(static_cast<Index>(i) * nr, static_cast<Index>(j) * nc, nr, nc) =
          system.linear_block(blocks[i], blocks[j], shift, rows, cols);
  return out;
}

}  // namespace

HillPencil::HillPencil(const HillSystem& system, double shift) : size_(system.size()) {
  const int n = system.dofs();
  const Index c = static_cast<Index>(system.coupled.size());
  std::vector<char> is_coupled(static_cast<size_t>(n), 0);
  for (int d : system.coupled) is_coupled[static_cast<size_t>(d)] = 1;
  std::vector<int> linear_dofs;
  for (int d = 0; d < n; ++d)
    if (!is_coupled[static_cast<size_t>(d)]) linear_dofs.push_back(d);
  for (int b = 0; b < system.blocks(); ++b)
    for (Index i = 0; i < c; ++i) schur_positions_.push_back(static_cast<Index>(b) * n + system.coupled[static_cast<size_t>(i)]);

  // The elements' part, then each harmonic's linear part on the coupled dofs less what its
  // linear dofs contribute through them.
  MatrixXd schur = system.element_jacobian + shift * system.element_damping;
  for (int first = 0; first < system.blocks();) {
    std::vector<int> blocks{first};
    while (blocks.back() + 1 < system.blocks() && system.basis->harmonic_of(blocks.back() + 1) == system.basis->harmonic_of(first))
      blocks.push_back(blocks.back() + 1);
    first = blocks.back() + 1;
    Group g;
    for (int b : blocks) {
      for (int d : linear_dofs) g.linear.push_back(static_cast<Index>(b) * n + d);
      for (Index i = 0; i < c; ++i) g.coupled_in_schur.push_back(b * c + i);
    }
    const Index gc = static_cast<Index>(g.coupled_in_schur.size());
    const MatrixXd coupled_part = group_block(system, blocks, shift, system.coupled, system.coupled);
    for (Index j = 0; j < gc; ++j)
      for (Index i = 0; i < gc; ++i) schur(g.coupled_in_schur[i], g.coupled_in_schur[j]) += coupled_part(i, j);
    if (!g.linear.empty()) {
      g.lu.compute(group_block(system, blocks, shift, linear_dofs, linear_dofs));
      g.to_linear = group_block(system, blocks, shift, linear_dofs, system.coupled);
      g.from_linear = group_block(system, blocks, shift, system.coupled, linear_dofs);
      const MatrixXd correction = g.from_linear * g.lu.solve(g.to_linear);
      for (Index j = 0; j < gc; ++j)
        for (Index i = 0; i < gc; ++i) schur(g.coupled_in_schur[i], g.coupled_in_schur[j]) -= correction(i, j);
    }
    groups_.push_back(std::move(g));
  }
  if (schur.size() > 0) schur_.compute(schur);
}

VectorXd HillPencil::solve(const VectorXd& r) const {
  VectorXd rhs = gather(r, schur_positions_);
  std::vector<VectorXd> linear_rhs(groups_.size());
  for (size_t k = 0; k < groups_.size(); ++k) {
    const Group& g = groups_[k];
    if (g.linear.empty()) continue;
    linear_rhs[k] = gather(r, g.linear);
    const VectorXd push = g.from_linear * g.lu.solve(linear_rhs[k]);
    for (size_t i = 0; i < g.coupled_in_schur.size(); ++i) rhs(g.coupled_in_schur[i]) -= push(static_cast<Index>(i));
  }
  if (rhs.size() > 0) schur_.solve_in_place(rhs);
  VectorXd y(size_);
  for (size_t i = 0; i < schur_positions_.size(); ++i) y(schur_positions_[i]) = rhs(static_cast<Index>(i));
  for (size_t k = 0; k < groups_.size(); ++k) {
    const Group& g = groups_[k];
    if (g.linear.empty()) continue;
    const VectorXd y_linear = g.lu.solve(linear_rhs[k] - g.to_linear * gather(rhs, g.coupled_in_schur));
    for (size_t i = 0; i < g.linear.size(); ++i) y(g.linear[i]) = y_linear(static_cast<Index>(i));
  }
  return y;
}

}  // namespace hbtrack
