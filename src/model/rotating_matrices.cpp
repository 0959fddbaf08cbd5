#include "hbtrack/model/rotating_matrices.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "hbtrack/model/sparse_modes.hpp"

namespace hbtrack {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// One point of the 3x3x3 Gauss rule on an element: shape values, their physical derivatives
// dN_a/dx_c and the weight times det J.
struct GaussPoint {
  Eigen::Matrix<double, kHex20Nodes, 1> values;
  Eigen::Matrix<double, kHex20Nodes, 3> derivatives;
  double weight = 0;
};

std::array<GaussPoint, 27> gauss_points(const Hex20Coordinates& nodes) {
  const double g = std::sqrt(0.6);
  const std::array<double, 3> points{-g, 0.0, g};
  const std::array<double, 3> weights{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  std::array<GaussPoint, 27> out;
  size_t q = 0;
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j)
      for (size_t k = 0; k < 3; ++k, ++q) {
        const Hex20Shape s = hex20_shape(Eigen::Vector3d(points[i], points[j], points[k]));
        const Eigen::Matrix3d jacobian = s.natural_derivatives.transpose() * nodes;
        const double det = jacobian.determinant();
        if (!(det > 0.0)) throw std::invalid_argument("hex20 element: non-positive Jacobian determinant (inverted or degenerate element)");
        out[q].values = s.values;
        out[q].derivatives = s.natural_derivatives * jacobian.inverse().transpose();
        out[q].weight = weights[i] * weights[j] * weights[k] * det;
      }
  return out;
}

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0, -a.z(), a.y(),  //
      a.z(), 0, -a.x(),   //
      -a.y(), a.x(), 0;
  return s;
}

// The element's scalar mass integrals int rho N_a N_b dV.
Eigen::Matrix<double, kHex20Nodes, kHex20Nodes> scalar_mass(const std::array<GaussPoint, 27>& points, double density) {
  Eigen::Matrix<double, kHex20Nodes, kHex20Nodes> nn = Eigen::Matrix<double, kHex20Nodes, kHex20Nodes>::Zero();
  for (const GaussPoint& p : points) nn.noalias() += density * p.weight * p.values * p.values.transpose();
  return nn;
}

// Each 3x3 block (a, b) of the element matrix: nn(a, b) * block.
Hex20Matrix node_blocks(const Eigen::Matrix<double, kHex20Nodes, kHex20Nodes>& nn, const Eigen::Matrix3d& block) {
  Hex20Matrix out;
  for (int a = 0; a < kHex20Nodes; ++a)
    for (int b = 0; b < kHex20Nodes; ++b) out.block<3, 3>(3 * a, 3 * b) = nn(a, b) * block;
  return out;
}

std::array<int, kHex20Dofs> global_dofs(const SolidMesh& mesh, const DofNumbering& dofs, int element) {
  std::array<int, kHex20Dofs> global{};
  const auto& connectivity = mesh.elements[static_cast<size_t>(element)];
  for (int a = 0; a < kHex20Nodes; ++a)
    for (int d = 0; d < 3; ++d) global[static_cast<size_t>(3 * a + d)] = dofs.dof(connectivity[static_cast<size_t>(a)], d);
  return global;
}

void scatter(const Hex20Matrix& element, const std::array<int, kHex20Dofs>& global, std::vector<Eigen::Triplet<double>>& entries) {
  for (int r = 0; r < kHex20Dofs; ++r) {
    const int gr = global[static_cast<size_t>(r)];
    if (gr < 0) continue;
    for (int c = 0; c < kHex20Dofs; ++c) {
      const int gc = global[static_cast<size_t>(c)];
      if (gc >= 0 && element(r, c) != 0.0) entries.emplace_back(gr, gc, element(r, c));
    }
  }
}

SparseMatrix from_triplets(int n, const std::vector<Eigen::Triplet<double>>& entries) {
  SparseMatrix out(n, n);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

}  // namespace

Hex20GaussStresses hex20_gauss_stresses(const Hex20Coordinates& nodes, const IsotropicMaterial& material,
                                        const Eigen::Matrix<double, kHex20Dofs, 1>& displacement) {
  const Eigen::Matrix<double, 6, 6> elasticity = material.elasticity_matrix();
  const std::array<GaussPoint, 27> points = gauss_points(nodes);
  Hex20GaussStresses out;
  for (size_t q = 0; q < points.size(); ++q) {
    // Displacement gradient H(i, j) = du_i/dx_j, engineering strain in Voigt order.
    Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
    for (int a = 0; a < kHex20Nodes; ++a) gradient += displacement.segment<3>(3 * a) * points[q].derivatives.row(a);
    Eigen::Matrix<double, 6, 1> strain;
    strain << gradient(0, 0), gradient(1, 1), gradient(2, 2), gradient(1, 2) + gradient(2, 1), gradient(0, 2) + gradient(2, 0),
        gradient(0, 1) + gradient(1, 0);
    const Eigen::Matrix<double, 6, 1> s = elasticity * strain;
    out[q] << s(0), s(5), s(4),  //
        s(5), s(1), s(3),        //
        s(4), s(3), s(2);
  }
  return out;
}

Hex20Matrix hex20_geometric_stiffness(const Hex20Coordinates& nodes, const Hex20GaussStresses& stresses) {
  const std::array<GaussPoint, 27> points = gauss_points(nodes);
  Eigen::Matrix<double, kHex20Nodes, kHex20Nodes> scalar = Eigen::Matrix<double, kHex20Nodes, kHex20Nodes>::Zero();
  for (size_t q = 0; q < points.size(); ++q)
    scalar.noalias() += points[q].weight * points[q].derivatives * stresses[q] * points[q].derivatives.transpose();
  return node_blocks(0.5 * (scalar + scalar.transpose()), Eigen::Matrix3d::Identity());
}

Hex20Matrix hex20_initial_displacement_stiffness(const Hex20Coordinates& nodes, const IsotropicMaterial& material,
                                                 const Eigen::Matrix<double, kHex20Dofs, 1>& displacement, bool quadratic) {
  const Eigen::Matrix<double, 6, 6> elasticity = material.elasticity_matrix();
  const std::array<GaussPoint, 27> points = gauss_points(nodes);
  Hex20Matrix out = Hex20Matrix::Zero();
  Eigen::Matrix<double, 6, kHex20Dofs> linear = Eigen::Matrix<double, 6, kHex20Dofs>::Zero(), first = linear;
  for (const GaussPoint& p : points) {
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();  // H(i, j) = du_i/dx_j
    for (int a = 0; a < kHex20Nodes; ++a) h += displacement.segment<3>(3 * a) * p.derivatives.row(a);
    for (int a = 0; a < kHex20Nodes; ++a) {
      const Eigen::RowVector3d g = p.derivatives.row(a);
      for (int d = 0; d < 3; ++d) {
        const int col = 3 * a + d;
        // Linear strain of dH = e_d g^T; its first-order change with u: sym(H^T dH), (H^T dH)_ij = H_di g_j.
        linear.col(col).setZero();
        linear(d, col) = g(d);
        const int shear_pairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
        for (int s = 0; s < 3; ++s) {
          const int i = shear_pairs[s][0], j = shear_pairs[s][1];
          linear(3 + s, col) = (d == i ? g(j) : 0.0) + (d == j ? g(i) : 0.0);
          first(3 + s, col) = h(d, i) * g(j) + h(d, j) * g(i);
        }
        for (int i = 0; i < 3; ++i) first(i, col) = h(d, i) * g(i);
      }
    }
    const Eigen::Matrix<double, 6, kHex20Dofs> db = elasticity * first;
    if (quadratic)
      out.noalias() += p.weight * (first.transpose() * db);
    else
      out.noalias() += p.weight * (linear.transpose() * db + db.transpose() * linear);
  }
  return 0.5 * (out + out.transpose());
}

RotatingMatrices assemble_rotating_hex20(const SolidMesh& mesh, const IsotropicMaterial& material, const DofNumbering& dofs,
                                         const SparseMatrix& stiffness, const RotationAxis& axis) {
  material.validate();
  if (!(axis.direction.norm() > 0) || !axis.direction.allFinite() || !axis.origin.allFinite())
    throw std::invalid_argument("rotation axis: the direction must be nonzero and the axis finite");
  const int n = dofs.free_dofs();
  if (dofs.nodes() != mesh.node_count()) throw std::invalid_argument("rotating matrices: dof numbering does not match the mesh");
  if (stiffness.rows() != n || stiffness.cols() != n)
    throw std::invalid_argument("rotating matrices: K is " + std::to_string(stiffness.rows()) + "x" + std::to_string(stiffness.cols()) +
                                ", the mesh has " + std::to_string(n) + " free dofs");
  const Eigen::Vector3d a = axis.direction.normalized();
  const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - a * a.transpose();
  const Eigen::Matrix3d cross = cross_matrix(a);

  RotatingMatrices out;
  out.centrifugal_load = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Triplet<double>> spin_entries, gyro_entries, geometric_entries, ku_entries, kuu_entries;
  const int elements = static_cast<int>(mesh.elements.size());
  for (int e = 0; e < elements; ++e) {
    const Hex20Coordinates x = mesh.element_coordinates(e);
    const auto nn = scalar_mass(gauss_points(x), material.density);
    const Hex20Matrix spin = node_blocks(nn, projector);
    const std::array<int, kHex20Dofs> global = global_dofs(mesh, dofs, e);
    scatter(spin, global, spin_entries);
    scatter(node_blocks(nn, 2.0 * cross), global, gyro_entries);
    // f1 = int rho N^T P (x - o) dV, with x = sum_b N_b x_b: M_spin_e times the nodes' positions.
    Eigen::Matrix<double, kHex20Dofs, 1> position;
    for (int b = 0; b < kHex20Nodes; ++b) position.segment<3>(3 * b) = x.row(b).transpose() - axis.origin;
    const Eigen::Matrix<double, kHex20Dofs, 1> load = spin * position;
    for (int r = 0; r < kHex20Dofs; ++r)
      if (global[static_cast<size_t>(r)] >= 0) out.centrifugal_load(global[static_cast<size_t>(r)]) += load(r);
  }
  out.spin_softening = from_triplets(n, spin_entries);
  out.gyroscopic = from_triplets(n, gyro_entries);

  const SparseLdlt factor(stiffness);
  if (factor.info() != Eigen::Success || (factor.vectorD().array() <= 0.0).any())
    throw std::runtime_error("rotating matrices: K is not positive definite (the constraints leave a rigid-body motion)");
  out.static_displacement = factor.solve(out.centrifugal_load);

  for (int e = 0; e < elements; ++e) {
    const std::array<int, kHex20Dofs> global = global_dofs(mesh, dofs, e);
    Eigen::Matrix<double, kHex20Dofs, 1> u = Eigen::Matrix<double, kHex20Dofs, 1>::Zero();
    for (int r = 0; r < kHex20Dofs; ++r)
      if (global[static_cast<size_t>(r)] >= 0) u(r) = out.static_displacement(global[static_cast<size_t>(r)]);
    const Hex20Coordinates x = mesh.element_coordinates(e);
    scatter(hex20_geometric_stiffness(x, hex20_gauss_stresses(x, material, u)), global, geometric_entries);
    scatter(hex20_initial_displacement_stiffness(x, material, u, false), global, ku_entries);
    scatter(hex20_initial_displacement_stiffness(x, material, u, true), global, kuu_entries);
  }
  out.geometric_stiffness = from_triplets(n, geometric_entries);
  out.initial_displacement_stiffness = from_triplets(n, ku_entries);
  out.second_order_stiffness = from_triplets(n, kuu_entries);
  return out;
}

SparseMatrix stiffness_at_speed(const SparseMatrix& stiffness, const RotatingMatrices& rotating, double speed) {
  const SparseMatrix change = rotating.geometric_stiffness - rotating.spin_softening;
  return stiffness + (speed * speed) * change;
}

}  // namespace hbtrack
