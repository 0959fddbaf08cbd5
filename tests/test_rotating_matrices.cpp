// The matrices of a rotating hex20 model (hbtrack/model/rotating_matrices.hpp) against
// independent computations: the geometric and initial-displacement stiffness against second
// differences of the Green-Lagrange strain energy of a displaced element, M_spin against the
// derivative of the centrifugal force of the displaced element integrated point by point, G's
// skew symmetry and its Coriolis force, and the static centrifugal stress of a radial bar against
// the analytic rho Omega^2 (R^2 - r^2) / 2.
#include <gtest/gtest.h>

#include <random>

#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/rotating_matrices.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_rotating_matrices {

namespace {

using namespace hbtrack;
using ElementVector = Eigen::Matrix<double, kHex20Dofs, 1>;

const IsotropicMaterial kSteel{210e9, 0.3, 7800.0};

// A distorted element (not a parallelepiped: the derivatives vary inside) about 10 mm wide.
Hex20Coordinates distorted_element() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.0006, 0.0006);
  Hex20Coordinates x;
  const auto& natural = hex20_natural_nodes();
  for (int a = 0; a < kHex20Nodes; ++a) {
    const auto& n = natural[static_cast<size_t>(a)];
    x.row(a) << 0.005 * n[0] + 0.001 * n[1] + jitter(random), 0.20 + 0.006 * n[1] + jitter(random),
        0.004 * n[2] + 0.0005 * n[0] * n[1] + jitter(random);
  }
  return x;
}

// Points and weights of the 3x3x3 rule, computed here on their own.
template <class F>
void for_each_gauss_point(const Hex20Coordinates& x, F f) {
  const double g = std::sqrt(0.6);
  const double points[3] = {-g, 0.0, g}, weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Hex20Shape s = hex20_shape(Eigen::Vector3d(points[i], points[j], points[k]));
        const Eigen::Matrix3d jacobian = s.natural_derivatives.transpose() * x;
        const Eigen::Matrix<double, kHex20Nodes, 3> dn = s.natural_derivatives * jacobian.inverse().transpose();
        f(s.values, dn, weights[i] * weights[j] * weights[k] * jacobian.determinant());
      }
}

// Green-Lagrange strain energy 1/2 int E : C : E dV of the element displaced by u.
double strain_energy(const Hex20Coordinates& x, const ElementVector& u) {
  const Eigen::Matrix<double, 6, 6> c = kSteel.elasticity_matrix();
  double energy = 0;
  for_each_gauss_point(x, [&](const auto&, const auto& dn, double w) {
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (int a = 0; a < kHex20Nodes; ++a) h += u.segment<3>(3 * a) * dn.row(a);
    const Eigen::Matrix3d e = 0.5 * (h + h.transpose() + h.transpose() * h);
    Eigen::Matrix<double, 6, 1> voigt;
    voigt << e(0, 0), e(1, 1), e(2, 2), 2 * e(1, 2), 2 * e(0, 2), 2 * e(0, 1);
    energy += 0.5 * w * voigt.dot(c * voigt);
  });
  return energy;
}

// The Hessian of the strain energy of the displaced element is, exactly, the total-Lagrangian
// tangent int B(u)^T C B(u) dV + K_sigma(S(u)), S = C E(u) the full second Piola-Kirchhoff
// stress: K + K_u1(u) + K_uu1(u) + K_sigma(S). The Hessian by central second differences (the
// energy is a quartic in u: its truncation error is of the order of the round-off here),
// at strains of 1e-2, where K_uu1 weighs 1e-2 of the change and K_u1 0.6; the stresses of S here
// from the Green-Lagrange strain computed on their own.
TEST(RotatingMatrices, HessianOfTheStrainEnergyIsTheTangentStiffness) {
  const Hex20Coordinates x = distorted_element();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  ElementVector u;
  for (int r = 0; r < kHex20Dofs; ++r) u(r) = 5e-5 * uniform(random);
  const Hex20Matrix k = hex20_element_matrices(x, kSteel).stiffness;
  Hex20GaussStresses full_stress;
  size_t q = 0;
  const Eigen::Matrix<double, 6, 6> c = kSteel.elasticity_matrix();
  for_each_gauss_point(x, [&](const auto&, const auto& dn, double) {
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (int a = 0; a < kHex20Nodes; ++a) h += u.segment<3>(3 * a) * dn.row(a);
    const Eigen::Matrix3d e = 0.5 * (h + h.transpose() + h.transpose() * h);
    Eigen::Matrix<double, 6, 1> voigt;
    voigt << e(0, 0), e(1, 1), e(2, 2), 2 * e(1, 2), 2 * e(0, 2), 2 * e(0, 1);
    const Eigen::Matrix<double, 6, 1> s = c * voigt;
    full_stress[q++] << s(0), s(5), s(4), s(5), s(1), s(3), s(4), s(3), s(2);
  });
  const Hex20Matrix ku = hex20_initial_displacement_stiffness(x, kSteel, u);
  const Hex20Matrix kuu = hex20_initial_displacement_stiffness(x, kSteel, u, /*quadratic=*/true);
  const Hex20Matrix predicted = k + ku + kuu + hex20_geometric_stiffness(x, full_stress);
  const double h = 1e-7;
  Hex20Matrix hessian;
  for (int i = 0; i < kHex20Dofs; ++i)
    for (int j = 0; j <= i; ++j) {
      ElementVector pp = u, pm = u, mp = u, mm = u;
      pp(i) += h, pp(j) += h, pm(i) += h, pm(j) -= h, mp(i) -= h, mp(j) += h, mm(i) -= h, mm(j) -= h;
      hessian(i, j) = hessian(j, i) =
          (strain_energy(x, pp) - strain_energy(x, pm) - strain_energy(x, mp) + strain_energy(x, mm)) / (4 * h * h);
    }
  const double change = (hessian - k).cwiseAbs().maxCoeff();
  EXPECT_GT(change, 1e-3 * k.cwiseAbs().maxCoeff());                      // the displacement's effect, far above round-off
  EXPECT_LT((hessian - predicted).cwiseAbs().maxCoeff(), 1e-6 * change);  // measured 4e-8: the differences' round-off
  // Each part matters at this size: leaving one out breaks the match by far more.
  for (const Hex20Matrix* part : {&ku, &kuu}) EXPECT_GT((hessian - predicted + *part).cwiseAbs().maxCoeff(), 1e-3 * change);
}

// A small blade: the centrifugal force of the displaced blade at unit speed,
// int rho P (x + u - o) dV integrated point by point here, is f1 + M_spin u (it is linear in u);
// the Coriolis force of a velocity v, int 2 rho a x v dV, is G v, and G is skew.
TEST(RotatingMatrices, SpinSofteningAndGyroscopicMatricesAreTheDerivativesOfTheInertiaForces) {
  BladeGeometry g;
  g.span_elements = 2;
  const BladeModel blade = generate_blade(g);
  const SolidMesh& mesh = blade.grid.mesh();
  const AssembledMatrices m = assemble_blade(blade);
  RotationAxis axis;
  axis.origin = Eigen::Vector3d(0.01, 0.0, -0.02);  // off the origin, and a tilted direction
  axis.direction = Eigen::Vector3d(1.0, 0.2, 0.1);
  const RotatingMatrices r = assemble_rotating_hex20(mesh, g.material, blade.dofs, m.stiffness, axis);
  const Eigen::Vector3d a = axis.direction.normalized();
  const int n = blade.dofs.free_dofs();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd u(n), v(n);
  for (int i = 0; i < n; ++i) u(i) = 1e-3 * uniform(random), v(i) = uniform(random);
  // Nodal field of a free-dof vector (clamped nodes: zero).
  auto nodal = [&](const Eigen::VectorXd& w, int e) {
    Eigen::Matrix<double, kHex20Nodes, 3> out = Eigen::Matrix<double, kHex20Nodes, 3>::Zero();
    for (int k = 0; k < kHex20Nodes; ++k)
      for (int d = 0; d < 3; ++d) {
        const int dof = blade.dofs.dof(mesh.elements[static_cast<size_t>(e)][static_cast<size_t>(k)], d);
        if (dof >= 0) out(k, d) = w(dof);
      }
    return out;
  };
  Eigen::VectorXd centrifugal = Eigen::VectorXd::Zero(n), coriolis = Eigen::VectorXd::Zero(n);
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
    const Hex20Coordinates x = mesh.element_coordinates(e);
    const auto ue = nodal(u, e), ve = nodal(v, e);
    for_each_gauss_point(x, [&](const auto& values, const auto&, double w) {
      const Eigen::Vector3d point = x.transpose() * values + ue.transpose() * values - axis.origin;
      const Eigen::Vector3d radial = point - a * a.dot(point);
      const Eigen::Vector3d cor = 2.0 * a.cross(Eigen::Vector3d(ve.transpose() * values));
      for (int k = 0; k < kHex20Nodes; ++k)
        for (int d = 0; d < 3; ++d) {
          const int dof = blade.dofs.dof(mesh.elements[static_cast<size_t>(e)][static_cast<size_t>(k)], d);
          if (dof < 0) continue;
          centrifugal(dof) += g.material.density * w * values(k) * radial(d);
          coriolis(dof) += g.material.density * w * values(k) * cor(d);
        }
    });
  }
  const Eigen::VectorXd predicted = r.centrifugal_load + r.spin_softening * u;
  EXPECT_LT((centrifugal - predicted).cwiseAbs().maxCoeff(), 1e-12 * centrifugal.cwiseAbs().maxCoeff());
  EXPECT_LT((coriolis - r.gyroscopic * v).cwiseAbs().maxCoeff(), 1e-12 * coriolis.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd gyro(r.gyroscopic);
  EXPECT_LT((gyro + gyro.transpose()).cwiseAbs().maxCoeff(), 1e-14 * gyro.cwiseAbs().maxCoeff());
  // The static displacement solves K u1 = f1.
  EXPECT_LT((m.stiffness * r.static_displacement - r.centrifugal_load).norm(), 1e-9 * r.centrifugal_load.norm());
}

// K(Omega) is the polynomial it is documented to be; a zero axis is refused.
TEST(RotatingMatrices, StiffnessAtSpeedIsThePolynomialInOmegaSquared) {
  BladeGeometry g;
  g.span_elements = 2;
  const BladeModel blade = generate_blade(g);
  const AssembledMatrices m = assemble_blade(blade);
  const RotatingMatrices r = assemble_rotating_hex20(blade.grid.mesh(), g.material, blade.dofs, m.stiffness, RotationAxis{});
  const double speed = 700.0;
  const Eigen::MatrixXd expected = Eigen::MatrixXd(m.stiffness) + speed * speed * Eigen::MatrixXd(r.geometric_stiffness - r.spin_softening);
  EXPECT_LT((Eigen::MatrixXd(stiffness_at_speed(m.stiffness, r, speed)) - expected).cwiseAbs().maxCoeff(),
            1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_THROW(assemble_rotating_hex20(blade.grid.mesh(), g.material, blade.dofs, m.stiffness, RotationAxis{{0, 0, 0}, {0, 0, 0}}),
               std::invalid_argument);
}

}  // namespace

}  // namespace hbtrack_tests::file_rotating_matrices
