#pragma once
// The linear part of the equation of motion M x'' + C x' + K x + f_nl = f_ext: constant matrices,
// named dofs and the harmonic forcing shape. Units are the model's own; frequencies in rad/s.
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace hbtrack {

// One harmonic of the external force: f(t) = amplitude * (cos_part cos(k w t) + sin_part sin(k w t)).
// Order 0 is a static load (only cos_part is used, as the full constant value).
struct HarmonicForce {
  int order = 1;
  Eigen::VectorXd cos_part;  // size n
  Eigen::VectorXd sin_part;  // size n
};

// A forcing that grows with the frequency (unbalance: exponent 2; engine-order forcing at varying
// speed): every HarmonicForce is multiplied by (omega / reference_frequency)^exponent, omega the
// forcing frequency. Exponent 0 (the default) is a fixed forcing and leaves it untouched.
struct ForcingGrowth {
  double exponent = 0.0;             // k >= 0
  double reference_frequency = 1.0;  // omega_ref > 0 [rad/s]: where the forcing is as given
  bool active() const { return exponent != 0.0; }
  // (omega / omega_ref)^k, exactly 1 when inactive.
  double factor(double omega) const;
  // d/d(omega) of factor: k / omega_ref (omega / omega_ref)^(k - 1), 0 when inactive.
  double derivative(double omega) const;
};

struct StructuralModel {
  std::vector<std::string> dof_names;  // size n, unique
  Eigen::MatrixXd mass;                // n x n, symmetric positive definite
  Eigen::MatrixXd damping;             // n x n
  Eigen::MatrixXd stiffness;           // n x n, symmetric
  std::vector<HarmonicForce> forcing;  // scaled by the named parameter `amplitude`
  ForcingGrowth forcing_growth;        // and by (omega / omega_ref)^k

  int dofs() const { return static_cast<int>(dof_names.size()); }
  // Index of a dof by name, or -1.
  int find_dof(const std::string& name) const;
  // Throws std::invalid_argument naming the rule broken (sizes, symmetry, definiteness).
  void validate() const;
};

}  // namespace hbtrack
