#include "hbtrack/model/craig_bampton.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hbtrack/model/sparse_modes.hpp"

namespace hbtrack {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The block of `a` with rows and columns picked by index maps (-1: not in the block).
SparseMatrix block(const SparseMatrix& a, const std::vector<int>& row_index, int rows, const std::vector<int>& col_index, int cols) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int outer = 0; outer < a.outerSize(); ++outer)
    for (SparseMatrix::InnerIterator it(a, outer); it; ++it) {
      const int r = row_index[static_cast<size_t>(it.row())], c = col_index[static_cast<size_t>(it.col())];
      if (r >= 0 && c >= 0) entries.emplace_back(r, c, it.value());
    }
  SparseMatrix out(rows, cols);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

Eigen::MatrixXd symmetric_part(const Eigen::MatrixXd& a) { return 0.5 * (a + a.transpose()); }

}  // namespace

std::vector<std::string> craig_bampton_dof_names(int boundary_nodes, int modes, const std::array<const char*, 3>& directions) {
  // Built with += : GCC 12 flags a spurious -Wrestrict on "n" + std::to_string(j) + suffix.
  auto name = [](char prefix, int number, const char* suffix) {
    std::string out(1, prefix);
    out += std::to_string(number);
    out += suffix;
    return out;
  };
  std::vector<std::string> names;
  for (int j = 1; j <= boundary_nodes; ++j)
    for (const char* direction : directions) names.push_back(name('n', j, direction));
  for (int m = 1; m <= modes; ++m) names.push_back(name('m', m, ""));
  return names;
}

Eigen::MatrixXd craig_bampton_project(const CraigBamptonModel& model, const SparseMatrix& full) {
  if (full.rows() != model.transformation.rows() || full.cols() != model.transformation.rows())
    throw std::invalid_argument("Craig-Bampton: a matrix to reduce must be " + std::to_string(model.transformation.rows()) +
                                " square, got " + std::to_string(full.rows()) + "x" + std::to_string(full.cols()));
  const Eigen::MatrixXd product = model.transformation.transpose() * (full * model.transformation);
  // Keep the input's symmetry exactly (round-off otherwise breaks it by 1e-16 relative).
  auto largest = [](const SparseMatrix& a) {
    double m = 0;
    for (int k = 0; k < a.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(a, k); it; ++it) m = std::max(m, std::abs(it.value()));
    return m;
  };
  const double scale = std::max(largest(full), 1e-300);
  const SparseMatrix transposed = full.transpose();
  const SparseMatrix asymmetry = full - transposed, skewness = full + transposed;
  if (largest(asymmetry) <= 1e-12 * scale) return symmetric_part(product);
  if (largest(skewness) <= 1e-12 * scale) return 0.5 * (product - product.transpose());
  return product;
}

CraigBamptonModel craig_bampton(const SparseMatrix& mass, const SparseMatrix& stiffness,
                                const std::vector<CraigBamptonBoundaryNode>& boundary, int fixed_interface_modes) {
  const int n = static_cast<int>(stiffness.rows());
  if (stiffness.cols() != n || mass.rows() != n || mass.cols() != n)
    throw std::invalid_argument("Craig-Bampton: M and K must be square and of the same size");
  if (boundary.empty()) throw std::invalid_argument("Craig-Bampton: needs at least one boundary node");
  const int boundary_dofs = 3 * static_cast<int>(boundary.size());
  const int interior_dofs = n - boundary_dofs;
  if (fixed_interface_modes < 0 || fixed_interface_modes > interior_dofs)
    throw std::invalid_argument("Craig-Bampton: " + std::to_string(fixed_interface_modes) +
                                " fixed-interface modes asked, the interior has " + std::to_string(std::max(interior_dofs, 0)) + " dofs");

  // Boundary dofs numbered in node order, interior dofs in their full-model order.
  std::vector<int> boundary_index(static_cast<size_t>(n), -1), interior_index(static_cast<size_t>(n), -1);
  for (size_t j = 0; j < boundary.size(); ++j)
    for (size_t d = 0; d < 3; ++d) {
      const int dof = boundary[j].dofs[d];
      if (dof < 0 || dof >= n)
        throw std::invalid_argument("Craig-Bampton: boundary node " + std::to_string(j + 1) + " has a dof outside the model");
      if (boundary_index[static_cast<size_t>(dof)] >= 0)
        throw std::invalid_argument("Craig-Bampton: dof " + std::to_string(dof + 1) + " is on the boundary twice");
      boundary_index[static_cast<size_t>(dof)] = static_cast<int>(3 * j + d);
    }
  std::vector<int> interior_dof_list;
  for (int dof = 0; dof < n; ++dof)
    if (boundary_index[static_cast<size_t>(dof)] < 0) {
      interior_index[static_cast<size_t>(dof)] = static_cast<int>(interior_dof_list.size());
      interior_dof_list.push_back(dof);
    }

  const SparseMatrix k_ii = block(stiffness, interior_index, interior_dofs, interior_index, interior_dofs);
  const SparseMatrix m_ii = block(mass, interior_index, interior_dofs, interior_index, interior_dofs);
  const SparseMatrix k_ib = block(stiffness, interior_index, interior_dofs, boundary_index, boundary_dofs);

  // Constraint modes: interior response to a unit displacement of each boundary dof, Psi = -K_ii^-1 K_ib.
  SparseLdlt k_ii_factor(k_ii);
  if (k_ii_factor.info() != Eigen::Success || (k_ii_factor.vectorD().array() <= 0.0).any())
    throw std::runtime_error(
        "Craig-Bampton: K_ii is not positive definite (the boundary and constraints do not fix the rigid-body motion)");
  const Eigen::MatrixXd constraint_modes = -k_ii_factor.solve(Eigen::MatrixXd(k_ib));

  CraigBamptonModel out;
  Eigen::MatrixXd fixed_modes(interior_dofs, fixed_interface_modes);
  if (fixed_interface_modes > 0) {
    const NormalModes modes = lowest_sparse_modes(k_ii_factor, k_ii, m_ii, fixed_interface_modes);
    fixed_modes = modes.shapes;
    out.fixed_interface_frequencies = modes.frequencies;
  }

  // T in global boundary coordinates, then the boundary columns turned into local frames:
  // u_b(global) = R u_b(local), R block-diagonal with each node's frame.
  const int reduced = boundary_dofs + fixed_interface_modes;
  out.transformation = Eigen::MatrixXd::Zero(n, reduced);
  for (int dof = 0; dof < n; ++dof) {
    const int b = boundary_index[static_cast<size_t>(dof)];
    if (b >= 0) {
      out.transformation(dof, b) = 1.0;
    } else {
      const int i = interior_index[static_cast<size_t>(dof)];
      out.transformation.row(dof).head(boundary_dofs) = constraint_modes.row(i);
      out.transformation.row(dof).tail(fixed_interface_modes) = fixed_modes.row(i);
    }
  }
  for (size_t j = 0; j < boundary.size(); ++j) {
    auto columns = out.transformation.middleCols<3>(static_cast<Eigen::Index>(3 * j));
    columns = (columns * boundary[j].frame).eval();
  }

  const Eigen::MatrixXd mass_t = mass * out.transformation;
  const Eigen::MatrixXd stiffness_t = stiffness * out.transformation;
  // Symmetric up to round-off; exact symmetry is what the case-file validation expects.
  out.mass = symmetric_part(out.transformation.transpose() * mass_t);
  out.stiffness = symmetric_part(out.transformation.transpose() * stiffness_t);
  out.dof_names = craig_bampton_dof_names(static_cast<int>(boundary.size()), fixed_interface_modes);
  return out;
}

}  // namespace hbtrack
