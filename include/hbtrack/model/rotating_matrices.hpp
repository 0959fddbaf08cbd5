#pragma once
// The matrices of a structure turning at a constant speed Omega about a fixed axis, written in
// the rotating frame (small vibrations about the centrifugally prestressed state):
//   M x'' + (C + Omega G) x' + (K + Omega^2 (K_g1 - M_spin)) x = f
// - M_spin, the spin softening: int rho N^T P N dV, P = I - a a^T the projector onto the plane
//   normal to the axis a (the centrifugal force of a displaced point grows with its distance);
// - G, the gyroscopic (Coriolis) matrix: int 2 rho N^T [a]x N dV, skew-symmetric;
// - K_g1, the geometric (stress) stiffness of the stress sigma1 = C eps(u1) of the linear
//   static centrifugal problem at unit speed, K u1 = f1, f1 = int rho N^T P (x - o) dV.
// This is linear prestress: the stress grows as Omega^2 on the undeformed shape. It neglects the
// static solve's own softening (K - Omega^2 M_spin instead of K) and its geometric nonlinearity
// (the blade's untwisting, NLGEOM). CalculiX's *STATIC step without NLGEOM followed by
// *FREQUENCY, PERTURBATION computes the tangent stiffness at the displaced shape Omega^2 u1:
//   K + Omega^2 (K_g1 + K_u1 - M_spin) + Omega^4 K_uu1,
// K_u1 and K_uu1 the initial-displacement stiffness (linear and quadratic in u1), assembled here
// too so that the test can match it; they are not in K(Omega): the Craig-Bampton basis of the
// blade at rest does not hold them (docs/analyses.md, "Rotating blades").
#include <Eigen/Sparse>

#include "hbtrack/model/fe_assembly.hpp"

namespace hbtrack {

struct RotationAxis {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // any length > 0; a positive speed turns about it by the right-hand rule
};

struct RotatingMatrices {
  Eigen::SparseMatrix<double> spin_softening;                  // M_spin, symmetric positive semi-definite
  Eigen::SparseMatrix<double> gyroscopic;                      // G, skew-symmetric
  Eigen::SparseMatrix<double> geometric_stiffness;             // K_g1, symmetric, at Omega = 1 rad/s
  Eigen::VectorXd centrifugal_load;                            // f1 over the free dofs, at Omega = 1 rad/s
  Eigen::VectorXd static_displacement;                         // u1 = K^-1 f1
  Eigen::SparseMatrix<double> initial_displacement_stiffness;  // K_u1, symmetric, at Omega = 1 rad/s (not in K(Omega))
  Eigen::SparseMatrix<double> second_order_stiffness;          // K_uu1, symmetric positive semi-definite (not in K(Omega))
};

// The stress tensor (3x3, symmetric) at each of the 27 points of the 3x3x3 Gauss rule (the
// first natural coordinate's index slowest) of an element with displacements u (node-major).
using Hex20GaussStresses = std::array<Eigen::Matrix3d, 27>;
Hex20GaussStresses hex20_gauss_stresses(const Hex20Coordinates& nodes, const IsotropicMaterial& material,
                                        const Eigen::Matrix<double, kHex20Dofs, 1>& displacement);
// The element's geometric stiffness of the given Gauss-point stresses:
//   K_g(3a + i, 3b + i) = int dN_a/dx^T S dN_b/dx dV.
Hex20Matrix hex20_geometric_stiffness(const Hex20Coordinates& nodes, const Hex20GaussStresses& stresses);

// The initial-displacement stiffness of the element displaced by u: the part of the total-
// Lagrangian tangent stiffness int B(u)^T C B(u) dV linear in u, int (B_L^T C B_1 + B_1^T C B_L)
// dV, or with `quadratic` the part quadratic in u, int B_1^T C B_1 dV; B_1 the derivative of the
// Green-Lagrange strain's quadratic part 1/2 H^T H at u (H the displacement gradient).
Hex20Matrix hex20_initial_displacement_stiffness(const Hex20Coordinates& nodes, const IsotropicMaterial& material,
                                                 const Eigen::Matrix<double, kHex20Dofs, 1>& displacement, bool quadratic = false);

// Assembles the three matrices over the free dofs of `dofs` and solves the static centrifugal
// problem with `stiffness` (the model's K over the same dofs). Throws std::invalid_argument for a
// zero axis, std::runtime_error when K is singular (the constraints leave a rigid motion).
RotatingMatrices assemble_rotating_hex20(const SolidMesh& mesh, const IsotropicMaterial& material, const DofNumbering& dofs,
                                         const Eigen::SparseMatrix<double>& stiffness, const RotationAxis& axis);

// K(Omega) = K + Omega^2 (K_g1 - M_spin), the stiffness the modes at speed Omega see.
Eigen::SparseMatrix<double> stiffness_at_speed(const Eigen::SparseMatrix<double>& stiffness, const RotatingMatrices& rotating,
                                               double speed);

}  // namespace hbtrack
