#pragma once
// The harmonic balance residual of a structural model with local nonlinear elements, condensed
// onto the retained dofs (paper eqs 9-11, 17-23):
//   R(x, omega) = Zr(omega) x + f_nl(x, omega) - amplitude * g(omega) * Fr(omega),
// g(omega) = (omega / omega_ref)^k the model's forcing growth (1 for a fixed forcing),
// with the nonlinear forces from the alternating frequency/time method and an analytic Jacobian.
// Unknowns: harmonic-major real coefficients of the retained dofs, size q(2H+1).
// HarmonicBalanceSystem is that system built once from a case and constant afterwards: it can be
// shared by every analysis and thread. What an evaluation depends on besides (x, omega) is
// passed to it: the parameter values, and a HarmonicBalanceWorkspace for its buffers (one per
// thread). HarmonicBalance (harmonic_balance.hpp) bundles the three for the common case.
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hbtrack/elements/nonlinear_element.hpp"
#include "hbtrack/hbm/adaptive_harmonics.hpp"
#include "hbtrack/hbm/fourier_basis.hpp"
#include "hbtrack/hbm/linear_condenser.hpp"
#include "hbtrack/model/parameters.hpp"
#include "hbtrack/model/structural_model.hpp"
#include "hbtrack/util/choices.hpp"

namespace hbtrack {

struct HarmonicBalanceOptions {
  int harmonics = 5;  // H, the largest harmonic balanced
  int samples = 0;    // N time samples per period; 0 picks a power of two >= 8(H+1)
  Condensation condensation = Condensation::automatic;
  // When not empty, the harmonics balanced (sorted, unique, >= 0, last = H; 0 only if listed),
  // e.g. {1, 3, 5, 7}; empty: 0..H. (After the first three: {H, N, condensation} still works.)
  std::vector<int> harmonic_list;
  // nu: the harmonics are multiples of omega / nu (1: of omega; 2: a period-doubled solution,
  // period 2 (2 pi / omega)). The forcing's harmonic h is harmonic h nu of the basis.
  int subharmonic = 1;
  // When enabled, an NFRC changes H along the branch within [min, max], starting from `harmonics`
  // (analysis/adaptive_nfrc.hpp); a system itself is built at one H.
  AdaptiveHarmonics adaptive;
  // Throws std::invalid_argument naming the field and the rule broken.
  void validate() const;
  int effective_samples() const;
  // The harmonics balanced: harmonic_list, or 0..H.
  std::vector<int> selected_harmonics() const;
  // Sets harmonic_list and H from a list (an empty list or 0..H is stored as H alone).
  void select(const std::vector<int>& list);
};

// The name of basis harmonic k in result columns: its multiple of omega, k / nu ("3", "0.5").
std::string harmonic_label(int k, int subharmonic);

// The frequency an element is handed: omega itself when its law depends on it explicitly (a
// casing's rotation speed), else the basis' fundamental omega / nu, whose period the samples span.
double element_frequency(const NonlinearElement& element, double omega, int subharmonic);

class HarmonicBalanceSystem;

// The buffers of a system's evaluations: time samples, the elements' responses, the condensed
// operators at the last frequency. Reused from one evaluation to the next so that the hot path
// does not allocate; not shareable between threads (one per thread).
class HarmonicBalanceWorkspace {
 public:
  explicit HarmonicBalanceWorkspace(const HarmonicBalanceSystem& system);

 private:
  friend class HarmonicBalanceSystem;
  struct ElementState {
    Eigen::MatrixXd x, v;  // N x k local samples
    Eigen::MatrixXd r;     // N x k samples of the linear residual (uses_linear_residual)
    ElementResponse response;
  };
  const HarmonicBalanceSystem* system_;  // the system it was sized for
  std::vector<ElementState> elements_;
  CondensedOperators condensed_;
  Eigen::MatrixXd x_samples_, v_unit_samples_;  // samples of all retained dofs
  Eigen::MatrixXd coefficient_rows_;            // the harmonics of x, (2H+1) x q: one row per coefficient
  Eigen::MatrixXd block_, block_v_, coeffs_, coeffs_v_;
  // Of nonlinear_adjoint_products: samples per retained dof (N x q) of the terms paired with the
  // displacement and with the unit-frequency velocity, and an element's samples of w (N x k).
  // The element's d f/d(omega) samples (N x k) serve evaluate too.
  Eigen::MatrixXd adjoint_x_, adjoint_v_, adjoint_local_, omega_samples_;
};

class HarmonicBalanceSystem {
 public:
  HarmonicBalanceSystem(StructuralModel model, ElementList elements, ParameterSet parameters, HarmonicBalanceOptions options);
  // Workspaces point to their system: it stays where it was built (held by a shared_ptr).
  HarmonicBalanceSystem(const HarmonicBalanceSystem&) = delete;
  HarmonicBalanceSystem& operator=(const HarmonicBalanceSystem&) = delete;

  int unknowns() const { return static_cast<int>(retained_.size()) * basis_.coefficients(); }
  int retained_dofs() const { return static_cast<int>(retained_.size()); }
  const std::vector<int>& retained() const { return retained_; }
  const FourierBasis& basis() const { return basis_; }
  const StructuralModel& model() const { return model_; }
  const ElementList& elements() const { return elements_; }
  // Throws std::invalid_argument naming the analysis when an element reads the linear residual
  // (law = "dlft"): analyses that add terms to the residual (EPMC) or need a time-domain law
  // (limit-point tracking's adjoint, Hill) have no meaning with it.
  void refuse_residual_elements(const std::string& analysis) const;
  const HarmonicBalanceOptions& options() const { return options_; }
  std::string condensation_method() const { return condenser_->method(); }
  // The parameters' names and the case's (nominal) values; "amplitude" always among them.
  const ParameterSet& parameters() const { return parameters_; }
  int amplitude_parameter() const { return amplitude_index_; }
  // True when an element's force has corners (NonlinearElement::force_has_corners): the
  // residual is then only piecewise smooth in x.
  bool has_corners() const {
    for (const auto& e : elements_)
      if (e->force_has_corners()) return true;
    return false;
  }
  // The basis' fundamental frequency omega / nu (harmonic k of the basis is at k omega / nu); the
  // solution's period is 2 pi / fundamental(omega).
  double fundamental(double omega) const { return omega / options_.subharmonic; }
  int subharmonic() const { return options_.subharmonic; }

  // Every evaluation below reads the parameter values `p` (ParameterSet order) and writes only
  // into the workspace `ws`, which must have been made for this system.

  // r = R(x, omega); optionally the Jacobian dR/dx and dR/d(omega).
  void evaluate(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega, Eigen::VectorXd& r,
                Eigen::MatrixXd* jacobian = nullptr, Eigen::VectorXd* r_omega = nullptr) const;
  // dR/d(parameter) at fixed x and omega, analytic.
  Eigen::VectorXd parameter_derivative(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega,
                                       int parameter) const;
  // Harmonic coefficients of every dof, n(2H+1) harmonic-major in the dense layout 0..H (zeros
  // for the harmonics not balanced), recovered from a solution x.
  Eigen::VectorXd expand(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega) const;
  // Solution of the linear system (nonlinear forces switched off) at omega, in unknown layout.
  Eigen::VectorXd linear_solution(const ParameterValues& p, HarmonicBalanceWorkspace& ws, double omega) const;
  // Solution of the system linearised about rest, x = -J(0)^-1 R(0): the elements' tangent at
  // zero displacement included (a stuck friction slider's stiffness, a preloaded contact), which
  // linear_solution ignores. One Newton step from zero.
  Eigen::VectorXd rest_linearized_solution(const ParameterValues& p, HarmonicBalanceWorkspace& ws, double omega) const;
  // Nonlinear force harmonics on the retained dofs (unknown layout), Lanczos filter included.
  Eigen::VectorXd nonlinear_forces(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega) const;
  // Each element's force over one period at the solution x (unknown layout): N x k samples on its
  // k local dofs at the AFT's instants tau_i = 2 pi i / N, before the Lanczos filter (the law's
  // force itself; harmonic_balance_element_forces.cpp).
  std::vector<Eigen::MatrixXd> element_force_samples(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x,
                                                     double omega) const;
  // Products of w with the nonlinear forces' derivatives, from one set of time samples and
  // without forming a q x q matrix (about one residual evaluation):
  // jacobian_transpose_w = J_nl(x, omega)^T w, J_nl = d f_nl/dx the nonlinear forces' part of
  // dR/dx (Lanczos filter and velocity dependence included); returns w . d f_nl/d(omega).
  double nonlinear_adjoint_products(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega,
                                    const Eigen::VectorXd& w, Eigen::VectorXd& jacobian_transpose_w) const;
  // d/d(omega) of the condensed linear stiffness applied to d, (dZr/d(omega)) d: the part of
  // R_omega that depends on x, without the forcing's.
  Eigen::VectorXd linear_omega_derivative(HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& d, double omega) const;
  // Matrices of Hill's quadratic eigenproblem (l^2 D2 + l D1 + J) p = 0 on the full,
  // uncondensed system (every dof, n x the basis' coefficients, harmonic-major: the Hill matrix
  // over the harmonics balanced), at the solution x (unknown layout), w the fundamental:
  //   jacobian = dR_full/dx_full,  damping = D1 = 2 w (nabla x M) + I x C + Gamma^-1 (df/dv) Gamma.
  // D2 = I x M is not formed.
  void hill_matrices(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega,
                     Eigen::MatrixXd& jacobian, Eigen::MatrixXd& damping) const;
  // The elements' parts of those two matrices alone, on the model dofs `coupled` (ascending, every
  // dof an element touches): (c nc) square, harmonic-major over `coupled`. The model's linear
  // part, which couples dofs only within a harmonic, is left to the caller (stability/hill_system.hpp).
  void hill_element_blocks(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega,
                           const std::vector<int>& coupled, Eigen::MatrixXd& jacobian, Eigen::MatrixXd& damping) const;

 private:
  using ElementState = HarmonicBalanceWorkspace::ElementState;
  struct ElementSlot {
    std::vector<int> columns;  // positions of the element's dofs among the retained dofs
    Eigen::VectorXd sigma;     // Lanczos factors per coefficient
  };
  // Throws std::logic_error when `ws` was made for another system, or `p` has the wrong size.
  void check(const ParameterValues& p, const HarmonicBalanceWorkspace& ws) const;
  void sample(HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega) const;
  // Samples at x and adds every element's Hill blocks, its dofs placed by `position` within
  // harmonic blocks of `stride` rows.
  void add_hill_element_blocks(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega, int stride,
                               const std::function<int(int)>& position, Eigen::MatrixXd& jacobian, Eigen::MatrixXd& damping) const;
  // Adds element e's Jacobian blocks; `positions` place its dofs within a harmonic block of
  // `stride` rows (retained-dof columns for the condensed system, model dofs for the full one).
  void add_element_blocks(HarmonicBalanceWorkspace& ws, size_t e, double omega, int stride, const std::vector<int>& positions,
                          Eigen::MatrixXd* jacobian, Eigen::MatrixXd* velocity_jacobian) const;
  // Adds Zr x - amplitude g(omega) Fr (and its derivatives), omega the forcing frequency.
  void add_condensed_linear_part(double amplitude, double omega, const CondensedOperators& at, const Eigen::VectorXd& x, Eigen::VectorXd& r,
                                 Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_omega) const;
  // What multiplies the unit forcing Fr at omega: amplitude g(omega).
  double forcing_scale(const ParameterValues& p, double omega) const;
  // Complex amplitude a - i b of the basis' harmonic number `slot` (its position in the list).
  Eigen::VectorXcd harmonic(const Eigen::VectorXd& x, int slot, int dofs) const;
  int slot_offset(int slot) const { return slot_offset_[static_cast<size_t>(slot)]; }
  // d f/d(omega) samples (N x k) of evaluated element e: velocity and explicit dependence.
  void omega_derivative_samples(const HarmonicBalanceWorkspace& ws, size_t e, Eigen::MatrixXd& df) const;

  // Elements that read the linear residual (DLFT; harmonic_balance_dlft.cpp).
  // Evaluates element e into its state, with the samples of r_lin (unknown layout) when it reads it.
  void evaluate_element(const ParameterValues& p, HarmonicBalanceWorkspace& ws, size_t e, double omega, const Eigen::VectorXd& r_lin,
                        bool want_property_derivatives) const;
  // The condensed linear part of the residual alone, Zr x - amplitude Fr.
  Eigen::VectorXd linear_residual(const ParameterValues& p, HarmonicBalanceWorkspace& ws, const Eigen::VectorXd& x, double omega) const;
  // out += diag(sigma) Gamma^-1 (d f / d r_lin) Gamma v at element e's rows, v in unknown layout
  // (d r_lin / d omega, d r_lin / d amplitude).
  void add_residual_response(const HarmonicBalanceWorkspace& ws, size_t e, const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  // jacobian += diag(sigma) Gamma^-1 (d f / d r_lin) Gamma L at element e's rows, L the
  // linear Jacobian's rows of its dofs (linear_jacobian: the linear part alone).
  void add_residual_coupling(const HarmonicBalanceWorkspace& ws, size_t e, const Eigen::MatrixXd& linear_jacobian,
                             Eigen::MatrixXd& jacobian) const;
  bool residual_elements_ = false;

  StructuralModel model_;
  ElementList elements_;
  ParameterSet parameters_;
  HarmonicBalanceOptions options_;
  FourierBasis basis_;
  std::vector<int> retained_;
  std::vector<int> slot_offset_;  // first coefficient of each listed harmonic
  std::unique_ptr<const LinearCondenser> condenser_;
  int amplitude_index_ = -1;
  std::vector<ElementSlot> slots_;
};

}  // namespace hbtrack
