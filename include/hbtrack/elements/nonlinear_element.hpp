#pragma once
// A local nonlinear element: forces on a few dofs computed pointwise in time from their
// displacements and velocities (the "time" half of the alternating frequency/time method).
// Elements see all N samples of a period at once so that the loop over samples stays inside
// one virtual call.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
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
// Where the memory fades instead of ending at events (friction in two directions, whose force
// keeps the direction of its past), that matrix would fill up: such an element leaves
// history_dforce_dx empty and sets history_operator, the same map applied to perturbations.
class HistorySensitivity {
 public:
  virtual ~HistorySensitivity() = default;
  // d f = S dx and S^T w, for batches of columns in the layout of history_dforce_dx
  // ((N k) x c, row t + N i).
  virtual Eigen::MatrixXd apply(const Eigen::MatrixXd& dx) const = 0;
  virtual Eigen::MatrixXd apply_transpose(const Eigen::MatrixXd& w) const = 0;
};

struct ElementResponse {
  Eigen::MatrixXd force;
  Eigen::MatrixXd dforce_dx;
  Eigen::SparseMatrix<double> history_dforce_dx;
  std::shared_ptr<const HistorySensitivity> history_operator;
  // Elements that read the linear residual (uses_linear_residual()): d f / d r as an operator,
  // layouts as history_operator's.
  std::shared_ptr<const HistorySensitivity> residual_operator;
  Eigen::MatrixXd dforce_dv;
  Eigen::MatrixXd dforce_domega;
  Eigen::MatrixXd dforce_dproperty;
};

// One time step of a history element (time integration, monodromy matrix): its m internal
// variables (slider positions; all zero at rest, x = 0) before the step and the local
// displacements at the step's end give the force there and the variables after the step (the
// return mapping of plasticity). The linearisation holds all its dependencies:
//   dforce_dx k x k,  dforce_dstate k x m (state before the step),
//   dstate_dx m x k,  dstate_dstate m x m.
struct HistoryStep {
  Eigen::VectorXd force, state;
  Eigen::MatrixXd dforce_dx, dforce_dstate, dstate_dx, dstate_dstate;
  // dstate_dstate is diagonal (each variable moves on its own, as parallel sliders do): users
  // may then skip its off-diagonal entries.
  bool diagonal_state = false;
};

// How a contact element's friction couples back into its normal load, for the static loop gain
// of src/analysis/friction_loop_gain.cpp. Local dof `normal` is positive towards the contact
// (closing the gap): the contact pushes the structure along -normal with its force f_N, and
// friction pushes it along `sense` * tangential with mu f_N while it slides.
struct FrictionCoupling {
  int normal = 0, tangential = 1;  // local dof indices
  double mu = 0;
  // d f_N / d x_n in contact (the penalty stiffness); 0 for a rigid contact (DLFT).
  double stiffness = 0;
  // +1 or -1 when the law fixes the sliding sense (a turning casing); 0 when the motion sets it
  // and friction may act either way.
  int sense = 0;
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
  // a whole period of N uniform samples. Time integration and the monodromy matrix step such an
  // element with the three history_* functions below instead.
  virtual bool history_dependent() const { return false; }
  // True when the internal variables are slider positions that start at 0 and stay put while
  // the slider sticks. Over a period of stick any position that keeps it stuck is periodic, so
  // periodic_history's is one choice among many (runs/sticking_slider_warnings.hpp).
  virtual bool stuck_slider_position_is_free() const { return false; }
  // Time-stepping form of a history element (zero internal variables for the others).
  virtual int history_state_size() const { return 0; }
  // The return mapping over one step of duration dt (dt matters only to a law that moves
  // on its own, such as a rotating casing): x is 1 x k, state has history_state_size() entries.
  virtual void history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                            const std::vector<double>& property_values, HistoryStep& out) const;
  // The internal variables after each of the N samples (N x m) of the periodic steady state that
  // evaluate() finds for the same samples: history_step from row t-1 to sample t gives row t.
  virtual Eigen::MatrixXd periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& property_values) const;
  // Why the force is not twice continuously differentiable ("" when it is): limit-point tracking
  // differentiates the Jacobian and cannot follow a fold through such a law.
  virtual std::string smoothness_limit() const { return ""; }
  // True when the sampled force is continuous but its Jacobian jumps where a sample changes
  // state (a penalty contact's gap, a slider's stick-slip transitions): the residual is then
  // piecewise smooth and its branches have corners, which the continuation steps over
  // (ContinuationProblem::has_corners).
  virtual bool force_has_corners() const { return false; }
  // Surfaces where the law's tangent jumps (a C0 law's corner), as signed functions of one
  // sample (x, v: 1 x k) that change sign there, so that time stepping can stop on them:
  // switching_surfaces() values written to `out`. None (0) for a law with a continuous tangent.
  virtual int switching_surfaces(const std::vector<double>& /*property_values*/) const { return 0; }
  virtual void switching_values(const Eigen::MatrixXd& /*x*/, const Eigen::MatrixXd& /*v*/, const std::vector<double>& /*property_values*/,
                                double* /*out*/) const {}
  // Evaluates forces and derivatives. x, v: N x k samples; property_values: one per property.
  virtual void evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& property_values,
                        ElementResponse& out, bool want_property_derivatives) const = 0;
  // The dynamic Lagrangian frequency/time method (DLFT, Nacivet et al. 2003: frictional_contact
  // with law = "dlft") computes contact forces from what the rest of the structure asks of the
  // contact: the linear part of the harmonic-balance residual at the element's dofs,
  //   r_lin = Zr(omega) x - amplitude Fr(omega)   (rows of the element's dofs, all harmonics),
  // as well as from the displacements. An element that does returns true here; the harmonic
  // balance then calls evaluate_with_residual with the samples of r_lin (N x k), the element
  // fills history_operator (d f / d x) and residual_operator (d f / d r_lin), and the harmonic
  // balance chains the latter with d r_lin / d(x, omega, amplitude). Its dofs may carry no other
  // element (r_lin would then not be what the contact balances), and it has no time-domain form
  // (time integration, stability) and no Lanczos filter.
  virtual bool uses_linear_residual() const { return false; }
  virtual void evaluate_with_residual(const Eigen::MatrixXd& x, const Eigen::MatrixXd& r, double omega,
                                      const std::vector<double>& property_values, ElementResponse& out,
                                      bool want_property_derivatives) const;

  // A contact element with Coulomb friction at frequency omega; nullopt for any other element.
  virtual std::optional<FrictionCoupling> friction_coupling(const std::vector<double>& /*property_values*/, double /*omega*/) const {
    return std::nullopt;
  }

  // What the element keeps outside the base class's fields (dofs, properties, Lanczos) that
  // shapes its force: a scalar element's weights, a law's choice, an Iwan's slider count. The
  // model's fingerprint (results/model_fingerprint.hpp) hashes it, so that a case edited there
  // does not resume a checkpoint of the old one. Default: nothing beyond the base class.
  virtual std::string configuration() const { return {}; }

  int local_dofs() const { return static_cast<int>(dofs.size()); }
  std::vector<double> property_values(const ParameterValues& parameters) const;
  std::vector<double> property_values(const ParameterSet& parameters) const { return property_values(parameters.values()); }

  std::vector<int> dofs;                     // model dof indices, size k
  std::vector<ParameterBinding> properties;  // one per property_names()
  // Lanczos sigma-factor exponent p applied to this element's force harmonics (0: no filter).
  double lanczos_exponent = 0.0;
};

using ElementList = std::vector<std::shared_ptr<NonlinearElement>>;

// Numbers as exact text ("%a": the double itself, not a rounding of it), for configuration().
std::string exact_text(const Eigen::Ref<const Eigen::VectorXd>& values);

// A history element's sensitivities d f_i(t) / d x_j(s) as a dense (N k) x (N k) matrix, from
// whichever form it returned (for tests and small checks).
Eigen::MatrixXd history_sensitivity_matrix(const ElementResponse& response, Eigen::Index samples, int dofs);

}  // namespace hbtrack
