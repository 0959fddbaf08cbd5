#pragma once
// A local nonlinear element: forces on a few dofs computed pointwise in time from their
// displacements and velocities (the "time" half of the alternating frequency/time method).
// Elements see all N samples of a period at once so that the loop over samples stays inside
// one virtual call.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "hbtrack/model/parameters.hpp"

namespace hbtrack {

// What an element returns for N samples of its k local dofs. Column layouts:
//   force          N x k
//   dforce_dx      N x (k*k), column i + k*j holds d f_i / d x_j
//   dforce_dv      N x (k*k), same layout (left empty when the element ignores velocity)
//   dforce_domega  N x k, explicit dependence on the forcing frequency (empty if none)
//   dforce_dproperty N x (k*P), column i + k*p holds d f_i / d property_p
// History-dependent elements (history_dependent() true: hysteresis, dry friction) return the
// periodic steady state of their internal variables, so the force at sample t depends on the
// displacements at earlier samples. They leave dforce_dx empty and fill instead
//   history_dforce_dx  sparse (N*k) x (N*k), entry (t + N*i, s + N*j) = d f_i(t) / d x_j(s),
// a compact form of the time-domain sensitivities (a Jenkins slider: two entries per sample,
// the sample itself and the last slip event) that the AFT turns into Fourier blocks.
struct ElementResponse {
  Eigen::MatrixXd force;
  Eigen::MatrixXd dforce_dx;
  Eigen::SparseMatrix<double> history_dforce_dx;
  Eigen::MatrixXd dforce_dv;
  Eigen::MatrixXd dforce_domega;
  Eigen::MatrixXd dforce_dproperty;
};

class NonlinearElement {
 public:
  virtual ~NonlinearElement() = default;

  virtual std::string type() const = 0;
  // Names of the scalar properties the element reads (stiffness, gap, mu, ...), in the order
  // of `properties` and of the columns of dforce_dproperty.
  virtual const std::vector<std::string>& property_names() const = 0;
  virtual bool depends_on_velocity() const = 0;
  virtual bool depends_on_omega() const { return false; }
  // True when the force depends on the past (see history_dforce_dx): evaluate() must then get
  // a whole period of N uniform samples, and pointwise users (time integration, monodromy)
  // refuse the element.
  virtual bool history_dependent() const { return false; }
  // Why the force is not twice continuously differentiable ("" when it is): limit-point tracking
  // differentiates the Jacobian and cannot follow a fold through such a law.
  virtual std::string smoothness_limit() const { return ""; }
  // Surfaces where the law's tangent jumps (a C0 law's corner), as signed functions of one
  // sample (x, v: 1 x k) that change sign there, so that time stepping can stop on them:
  // switching_surfaces() values written to `out`. None (0) for a law with a continuous tangent.
  virtual int switching_surfaces(const std::vector<double>& /*property_values*/) const { return 0; }
  virtual void switching_values(const Eigen::MatrixXd& /*x*/, const Eigen::MatrixXd& /*v*/,
                                const std::vector<double>& /*property_values*/, double* /*out*/) const {}
  // Evaluates forces and derivatives. x, v: N x k samples; property_values: one per property.
  virtual void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega,
                        const std::vector<double>& property_values, ElementResponse& out,
                        bool want_property_derivatives) const = 0;

  int local_dofs() const { return static_cast<int>(dofs.size()); }
  std::vector<double> property_values(const ParameterSet& parameters) const;

  std::vector<int> dofs;                     // model dof indices, size k
  std::vector<ParameterBinding> properties;  // one per property_names()
  // Lanczos sigma-factor exponent p applied to this element's force harmonics (0: no filter).
  double lanczos_exponent = 0.0;
};

using ElementList = std::vector<std::shared_ptr<NonlinearElement>>;

}  // namespace hbtrack
