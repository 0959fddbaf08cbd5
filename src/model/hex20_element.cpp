#include "hbtrack/model/hex20_element.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

const std::array<std::array<int, 3>, kHex20Nodes>& hex20_natural_nodes() {
  static const std::array<std::array<int, 3>, kHex20Nodes> nodes{{
      {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},   {-1, 1, 1}, {0, -1, -1}, {1, 0, -1},
      {0, 1, -1},   {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},   {0, 1, 1},   {-1, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},   {-1, 1, 0},
  }};
  return nodes;
}

Hex20Shape hex20_shape(const Eigen::Vector3d& xi) {
  Hex20Shape s;
  const auto& nodes = hex20_natural_nodes();
  for (int a = 0; a < kHex20Nodes; ++a) {
    const auto& n = nodes[static_cast<size_t>(a)];
    int zero_axis = -1;
    for (int j = 0; j < 3; ++j)
      if (n[static_cast<size_t>(j)] == 0) zero_axis = j;
    if (zero_axis < 0) {
      // Corner: 1/8 prod(1 + xi_j n_j) (sum_j xi_j n_j - 2).
      Eigen::Vector3d linear;
      for (int j = 0; j < 3; ++j) linear(j) = 1.0 + xi(j) * n[static_cast<size_t>(j)];
      const double sum = xi(0) * n[0] + xi(1) * n[1] + xi(2) * n[2] - 2.0;
      const double product = linear.prod();
      s.values(a) = 0.125 * product * sum;
      for (int j = 0; j < 3; ++j) {
        const double others = linear((j + 1) % 3) * linear((j + 2) % 3);  // no division: linear(j) may be 0
        s.natural_derivatives(a, j) = 0.125 * n[static_cast<size_t>(j)] * others * (sum + linear(j));
      }
    } else {
      // Mid-edge node on the edge along `zero_axis`: 1/4 (1 - xi_0^2) (1 + xi_1 n_1) (1 + xi_2 n_2).
      const int b = (zero_axis + 1) % 3, c = (zero_axis + 2) % 3;
      const double bubble = 1.0 - xi(zero_axis) * xi(zero_axis);
      const double lb = 1.0 + xi(b) * n[static_cast<size_t>(b)], lc = 1.0 + xi(c) * n[static_cast<size_t>(c)];
      s.values(a) = 0.25 * bubble * lb * lc;
      s.natural_derivatives(a, zero_axis) = -0.5 * xi(zero_axis) * lb * lc;
      s.natural_derivatives(a, b) = 0.25 * bubble * n[static_cast<size_t>(b)] * lc;
      s.natural_derivatives(a, c) = 0.25 * bubble * lb * n[static_cast<size_t>(c)];
    }
  }
  return s;
}

Hex20ElementMatrices hex20_element_matrices(const Hex20Coordinates& nodes, const IsotropicMaterial& material) {
  // 3-point Gauss-Legendre rule per direction: exact for the mass (degree 4 per direction on an
  // affine element) and the full-integration rule for the stiffness (no spurious zero-energy modes).
  const double g = std::sqrt(0.6);
  const std::array<double, 3> points{-g, 0.0, g};
  const std::array<double, 3> weights{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const Eigen::Matrix<double, 6, 6> elasticity = material.elasticity_matrix();

  Hex20ElementMatrices out;
  out.stiffness.setZero();
  out.mass.setZero();
  Eigen::Matrix<double, 6, kHex20Dofs> strain_displacement = Eigen::Matrix<double, 6, kHex20Dofs>::Zero();
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j)
      for (size_t k = 0; k < 3; ++k) {
        const Hex20Shape s = hex20_shape(Eigen::Vector3d(points[i], points[j], points[k]));
        const Eigen::Matrix3d jacobian = s.natural_derivatives.transpose() * nodes;  // d x_c / d xi_r
        const double det = jacobian.determinant();
        if (!(det > 0.0)) throw std::invalid_argument("hex20 element: non-positive Jacobian determinant (inverted or degenerate element)");
        const Eigen::Matrix<double, kHex20Nodes, 3> dn = s.natural_derivatives * jacobian.inverse().transpose();
        const double weight = weights[i] * weights[j] * weights[k] * det;
        for (int a = 0; a < kHex20Nodes; ++a) {
          const double dx = dn(a, 0), dy = dn(a, 1), dz = dn(a, 2);
          auto column = strain_displacement.middleCols<3>(3 * a);
          column << dx, 0, 0,  //
              0, dy, 0,        //
              0, 0, dz,        //
              0, dz, dy,       //
              dz, 0, dx,       //
              dy, dx, 0;
        }
        out.stiffness.noalias() += weight * strain_displacement.transpose() * elasticity * strain_displacement;
        const Eigen::Matrix<double, kHex20Nodes, kHex20Nodes> nn = material.density * weight * s.values * s.values.transpose();
        for (int a = 0; a < kHex20Nodes; ++a)
          for (int b = 0; b < kHex20Nodes; ++b)
            for (int d = 0; d < 3; ++d) out.mass(3 * a + d, 3 * b + d) += nn(a, b);
      }
  // Symmetric by construction up to round-off; make it exact so assembled matrices are too.
  out.stiffness = 0.5 * (out.stiffness + out.stiffness.transpose()).eval();
  return out;
}

}  // namespace hbtrack
