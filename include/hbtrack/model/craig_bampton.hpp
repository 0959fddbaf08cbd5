#pragma once
// Craig-Bampton reduction: a sparse model reduced to the translations of a few boundary nodes
// (static constraint modes) plus fixed-interface modes (boundary clamped). The boundary dofs are
// turned into each node's local frame, so the reduced dofs are
//   [n1_r, n1_t, n1_z, ..., nB_r, nB_t, nB_z, m1, ..., mM]
// (radial, circumferential, axial displacement of boundary node j, then modal amplitudes), the
// dofs the tip contact element expects.
#include <Eigen/Sparse>
#include <array>
#include <string>
#include <vector>

namespace hbtrack {

struct CraigBamptonBoundaryNode {
  std::array<int, 3> dofs{};                            // full-model rows of its x, y, z translations
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // columns: local r, t, z in x, y, z
};

struct CraigBamptonModel {
  Eigen::MatrixXd mass, stiffness;              // reduced, (3 B + M) square, symmetric
  Eigen::MatrixXd transformation;               // full x reduced: x_full = T q
  Eigen::VectorXd fixed_interface_frequencies;  // rad/s, the M kept modes
  std::vector<std::string> dof_names;
};

// M and K are the full model's (constraints already removed, K positive definite once the
// boundary is fixed). Uses one sparse LDL^T of K_ii for the constraint modes and a shift-invert
// Lanczos for the fixed-interface modes. Throws std::invalid_argument for bad input (a dof out
// of range or used twice, too many modes) and std::runtime_error when a solve fails.
CraigBamptonModel craig_bampton(const Eigen::SparseMatrix<double>& mass, const Eigen::SparseMatrix<double>& stiffness,
                                const std::vector<CraigBamptonBoundaryNode>& boundary, int fixed_interface_modes);

// T^T A T: another full-model matrix (the rotating blade's K_g1, K_g2, M_spin, G) on the same
// basis. Symmetric or skew-symmetric inputs give exactly symmetric or skew-symmetric outputs.
Eigen::MatrixXd craig_bampton_project(const CraigBamptonModel& model, const Eigen::SparseMatrix<double>& full);

// Reduced dof names for B boundary nodes and M modes: n1_r, n1_t, n1_z, ..., m1, ...
// `directions`: the suffixes of a boundary node's three dofs (the local r, t, z by default).
std::vector<std::string> craig_bampton_dof_names(int boundary_nodes, int modes,
                                                 const std::array<const char*, 3>& directions = {"_r", "_t", "_z"});

}  // namespace hbtrack
