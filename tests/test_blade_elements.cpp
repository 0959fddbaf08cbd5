// The 20-node hexahedron: shape functions, rigid-body modes, the constant-strain patch test, the
// consistent mass, and a cantilever's first bending frequency against Euler-Bernoulli.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "hbtrack/model/fe_assembly.hpp"
#include "hbtrack/model/hex20_element.hpp"
#include "hbtrack/model/solid_mesh.hpp"
#include "hbtrack/model/sparse_modes.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_blade_elements {

namespace {

using namespace hbtrack;

const IsotropicMaterial kTitanium{108e9, 0.34, 4400.0};

// A brick 2 x 1 x 0.5 with every node moved a little (edges curved), positive Jacobian throughout.
Hex20Coordinates distorted_brick() {
  Hex20Coordinates xyz;
  const auto& natural = hex20_natural_nodes();
  for (int a = 0; a < kHex20Nodes; ++a) {
    const auto& n = natural[static_cast<size_t>(a)];
    xyz(a, 0) = 1.0 * (1 + n[0]) + 0.05 * n[1] * n[2] + 0.03 * std::sin(a);
    xyz(a, 1) = 0.5 * (1 + n[1]) + 0.04 * n[0] + 0.02 * std::cos(3 * a);
    xyz(a, 2) = 0.25 * (1 + n[2]) - 0.03 * n[0] * n[1] + 0.01 * std::sin(5 * a);
  }
  return xyz;
}

TEST(Hex20, ShapeFunctionsAreNodalAndSumToOne) {
  const auto& natural = hex20_natural_nodes();
  for (int b = 0; b < kHex20Nodes; ++b) {
    const auto& n = natural[static_cast<size_t>(b)];
    const Hex20Shape s = hex20_shape(Eigen::Vector3d(n[0], n[1], n[2]));
    for (int a = 0; a < kHex20Nodes; ++a) EXPECT_NEAR(s.values(a), a == b ? 1.0 : 0.0, 1e-14);
  }
  const Eigen::Vector3d xi(0.3, -0.7, 0.45);
  const Hex20Shape s = hex20_shape(xi);
  EXPECT_NEAR(s.values.sum(), 1.0, 1e-14);
  EXPECT_LT(s.natural_derivatives.colwise().sum().cwiseAbs().maxCoeff(), 1e-14);
  // Derivatives against central differences.
  const double h = 1e-6;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d plus = xi, minus = xi;
    plus(j) += h;
    minus(j) -= h;
    const Eigen::VectorXd fd = (hex20_shape(plus).values - hex20_shape(minus).values) / (2 * h);
    EXPECT_LT((fd - s.natural_derivatives.col(j)).cwiseAbs().maxCoeff(), 1e-8) << "direction " << j;
  }
}

TEST(Hex20, SingleElementHasExactlySixRigidBodyModes) {
  const Hex20ElementMatrices e = hex20_element_matrices(distorted_brick(), kTitanium);
  EXPECT_LT((e.stiffness - e.stiffness.transpose()).cwiseAbs().maxCoeff(), 1e-12 * e.stiffness.cwiseAbs().maxCoeff());
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Hex20Matrix>(e.stiffness).eigenvalues();
  const double largest = eigenvalues.maxCoeff();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(eigenvalues(i)), 1e-10 * largest) << "eigenvalue " << i;
  // Full 3x3x3 integration: no spurious zero-energy (hourglass) mode.
  EXPECT_GT(eigenvalues(6), 1e-4 * largest);
}

TEST(Hex20, ConsistentMassCarriesTheElementMass) {
  // An undistorted box: the mass is rho * volume in each direction, and the matrix is positive definite.
  Hex20Coordinates box;
  const auto& natural = hex20_natural_nodes();
  for (int a = 0; a < kHex20Nodes; ++a)
    for (int d = 0; d < 3; ++d) box(a, d) = 0.5 * (1 + natural[static_cast<size_t>(a)][static_cast<size_t>(d)]) * (d + 1) * 0.1;
  const Hex20ElementMatrices e = hex20_element_matrices(box, kTitanium);
  const double mass = kTitanium.density * 0.1 * 0.2 * 0.3;
  for (int d = 0; d < 3; ++d) {
    double sum = 0;
    for (int a = 0; a < kHex20Nodes; ++a)
      for (int b = 0; b < kHex20Nodes; ++b) sum += e.mass(3 * a + d, 3 * b + d);
    EXPECT_NEAR(sum, mass, 1e-12 * mass);
  }
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Hex20Matrix>(e.mass).eigenvalues().minCoeff(), 0.0);
}

TEST(Hex20, PatchTestReproducesALinearDisplacementField) {
  // 2 x 2 x 2 elements with distorted (curved) interior: boundary nodes follow u = A x + b, the
  // interior nodes are solved for; a conforming isoparametric mesh reproduces the field exactly.
  const StructuredHex20Grid grid({2, 2, 2}, [](const Eigen::Vector3d& u) {
    const double bubble = std::sin(std::numbers::pi * u.x()) * std::sin(std::numbers::pi * u.y()) * std::sin(std::numbers::pi * u.z());
    return Eigen::Vector3d(1.0 * u.x() + 0.08 * bubble, 0.8 * u.y() - 0.05 * bubble, 0.6 * u.z() + 0.06 * bubble);
  });
  Eigen::Matrix3d a;
  a << 1e-3, 2e-4, -3e-4, 5e-4, -1e-3, 1e-4, -2e-4, 3e-4, 7e-4;
  const Eigen::Vector3d b(1e-4, -2e-4, 3e-4);
  const SolidMesh& mesh = grid.mesh();
  std::vector<bool> on_boundary(static_cast<size_t>(mesh.node_count()), false);
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j <= 4; ++j)
      for (int i = 0; i <= 4; ++i) {
        const int node = grid.node_at(i, j, k);
        if (node >= 0 && (i == 0 || i == 4 || j == 0 || j == 4 || k == 0 || k == 4)) on_boundary[static_cast<size_t>(node)] = true;
      }
  const AssembledMatrices all = assemble_hex20(mesh, kTitanium, DofNumbering(std::vector<bool>(on_boundary.size(), false)));
  const DofNumbering interior(on_boundary);
  ASSERT_GT(interior.free_dofs(), 0);
  // K_ii u_i = -K_ib u_b, with every node's prescribed value u(x) = A x + b.
  Eigen::VectorXd exact(3 * mesh.node_count());
  for (int n = 0; n < mesh.node_count(); ++n) exact.segment<3>(3 * n) = a * mesh.nodes[static_cast<size_t>(n)] + b;
  Eigen::VectorXd prescribed = exact;
  for (int n = 0; n < mesh.node_count(); ++n)
    if (!on_boundary[static_cast<size_t>(n)]) prescribed.segment<3>(3 * n).setZero();
  const Eigen::VectorXd rhs_full = -(all.stiffness * prescribed);
  const AssembledMatrices free = assemble_hex20(mesh, kTitanium, interior);
  Eigen::VectorXd rhs(interior.free_dofs());
  for (int n = 0; n < mesh.node_count(); ++n)
    for (int d = 0; d < 3; ++d)
      if (interior.dof(n, d) >= 0) rhs(interior.dof(n, d)) = rhs_full(3 * n + d);
  const Eigen::VectorXd solved = Eigen::MatrixXd(free.stiffness).ldlt().solve(rhs);
  double worst = 0;
  for (int n = 0; n < mesh.node_count(); ++n)
    for (int d = 0; d < 3; ++d)
      if (interior.dof(n, d) >= 0) worst = std::max(worst, std::abs(solved(interior.dof(n, d)) - exact(3 * n + d)));
  EXPECT_LT(worst, 1e-12);
}

TEST(Hex20, CantileverFirstBendingMatchesEulerBernoulli) {
  // Steel-like square beam, L / h = 20, 2 x 2 x 16 elements, clamped at one end. Euler-Bernoulli:
  // w1 = 1.8751^2 sqrt(E I / (rho A L^4)). Shear and rotary inertia lower the 3D result by about
  // 0.3 % at this slenderness and the clamped face (Poisson) stiffens it slightly: 1 % bounds both.
  const double length = 1.0, side = 0.05;
  const IsotropicMaterial steel{210e9, 0.3, 7800.0};
  const StructuredHex20Grid grid({2, 2, 16},
                                 [&](const Eigen::Vector3d& u) { return Eigen::Vector3d(side * u.x(), side * u.y(), length * u.z()); });
  std::vector<bool> clamped(static_cast<size_t>(grid.mesh().node_count()), false);
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i)
      if (const int node = grid.node_at(i, j, 0); node >= 0) clamped[static_cast<size_t>(node)] = true;
  const DofNumbering dofs(clamped);
  const AssembledMatrices m = assemble_hex20(grid.mesh(), steel, dofs);
  const NormalModes modes = lowest_sparse_modes(m.stiffness, m.mass, 2);
  const double inertia = std::pow(side, 4) / 12.0, area = side * side;
  const double beam = std::pow(1.8751040687, 2) * std::sqrt(steel.youngs_modulus * inertia / (steel.density * area * std::pow(length, 4)));
  // The square section bends equally in x and y: the two lowest modes coincide.
  EXPECT_NEAR(modes.frequencies(0) / beam, 1.0, 0.01);
  EXPECT_NEAR(modes.frequencies(1) / modes.frequencies(0), 1.0, 1e-6);
}

}  // namespace

}  // namespace hbtrack_tests::file_blade_elements
