#pragma once
// The 20-node serendipity hexahedron (quadratic, CalculiX/Abaqus C3D20 node order): shape
// functions and the element stiffness and consistent mass of isotropic linear elasticity by
// 3x3x3 Gauss integration. Element dofs are node-major: dof 3a + d is direction d of node a.
#include <array>

#include "hbtrack/model/elastic_material.hpp"

namespace hbtrack {

constexpr int kHex20Nodes = 20;
constexpr int kHex20Dofs = 3 * kHex20Nodes;

using Hex20Coordinates = Eigen::Matrix<double, kHex20Nodes, 3>;  // row a: x, y, z of node a
using Hex20Matrix = Eigen::Matrix<double, kHex20Dofs, kHex20Dofs>;

// Natural coordinates (each -1, 0 or 1) of the 20 nodes: corners 1-8 (bottom face counter-
// clockwise, then top), mid-edge nodes 9-12 (bottom), 13-16 (top), 17-20 (vertical edges).
const std::array<std::array<int, 3>, kHex20Nodes>& hex20_natural_nodes();

// Shape function values N_a and their derivatives dN_a/dxi_j at natural point xi.
struct Hex20Shape {
  Eigen::Matrix<double, kHex20Nodes, 1> values;
  Eigen::Matrix<double, kHex20Nodes, 3> natural_derivatives;
};
Hex20Shape hex20_shape(const Eigen::Vector3d& xi);

struct Hex20ElementMatrices {
  Hex20Matrix stiffness;
  Hex20Matrix mass;
};
// Throws std::invalid_argument when the element is inverted or degenerate (det J <= 0 at a
// Gauss point).
Hex20ElementMatrices hex20_element_matrices(const Hex20Coordinates& nodes, const IsotropicMaterial& material);

}  // namespace hbtrack
