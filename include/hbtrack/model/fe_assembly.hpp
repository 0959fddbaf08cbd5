#pragma once
// Assembly of a hex20 mesh into global sparse mass and stiffness matrices over the free dofs
// (constrained dofs are removed, not penalised).
#include <Eigen/Sparse>
#include <vector>

#include "hbtrack/model/solid_mesh.hpp"

namespace hbtrack {

// Numbers the free translational dofs node by node: free dof of (node, direction) or -1 when
// constrained. Nodes keep their mesh order, so a node's free dofs are consecutive.
class DofNumbering {
 public:
  // `clamped[n]` removes all three dofs of node n.
  explicit DofNumbering(const std::vector<bool>& clamped);
  int dof(int node, int direction) const { return dofs_[static_cast<size_t>(3 * node + direction)]; }
  int free_dofs() const { return free_; }
  int nodes() const { return static_cast<int>(dofs_.size() / 3); }
  // Free nodes in dof order: node k of this list owns free dofs 3k, 3k + 1, 3k + 2.
  std::vector<int> free_nodes() const;

 private:
  std::vector<int> dofs_;
  int free_ = 0;
};

struct AssembledMatrices {
  Eigen::SparseMatrix<double> mass;
  Eigen::SparseMatrix<double> stiffness;
};

// Consistent mass and stiffness of every element, summed over the free dofs. Throws
// std::invalid_argument for a bad material or an inverted element.
AssembledMatrices assemble_hex20(const SolidMesh& mesh, const IsotropicMaterial& material, const DofNumbering& dofs);

}  // namespace hbtrack
