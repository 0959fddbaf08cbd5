#pragma once
// Reader for the matrices CalculiX (ccx) writes with `*FREQUENCY, SOLVER=MATRIXSTORAGE`
// (*MATRIX STORAGE in the ccx manual): jobname.sti (stiffness) and jobname.mas (mass) hold one
// triangle of the symmetric matrix as `row column value` lines, 1-based (ccx writes the upper
// triangle); jobname.dof names the dof of each row as `node.direction` (e.g. `12.3`: node 12,
// z). Constrained dofs are absent. Every failure throws std::runtime_error with one line
// "<path>: line N: <rule>".
#include <Eigen/Sparse>
#include <string>
#include <vector>

namespace hbtrack {

// CalculiX numbering: direction 1, 2, 3 = x, y, z translation (0 temperature, 4-6 rotations).
struct CalculixDof {
  int node = 0;
  int direction = 0;
};

// One `node.direction` per line, in matrix row order.
std::vector<CalculixDof> read_calculix_dof_map(const std::string& path);

// A symmetric matrix from one triangle (either, but not both; duplicates are an error) of
// `rows` x `rows`; rows < 0 takes the largest index found.
Eigen::SparseMatrix<double> read_calculix_matrix(const std::string& path, int rows = -1);

struct CalculixMatrices {
  Eigen::SparseMatrix<double> stiffness, mass;
  std::vector<CalculixDof> dofs;  // one per row
};
// jobname.sti, jobname.mas and jobname.dof, sized by the dof map.
CalculixMatrices read_calculix_matrices(const std::string& jobname);

}  // namespace hbtrack
