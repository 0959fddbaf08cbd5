#pragma once
// An evaluator of the harmonic balance residual: a shared, constant HarmonicBalanceSystem, the
// parameter values it is evaluated at, and its own workspace. Copies share the system and own
// their values and buffers, so an analysis that needs other parameter values (a continuation in
// a parameter, limit-point tracking, the outputs of a point elsewhere on a curve) takes a const
// reference to its caller's evaluator and makes its own: the caller's values never change.
// Not thread-safe (its workspace): one evaluator per thread, all on the same system.
#include <memory>

#include "hbtrack/hbm/harmonic_balance_system.hpp"

namespace hbtrack {

class HarmonicBalance {
 public:
  // Builds the system, evaluated at the parameters' own values.
  HarmonicBalance(StructuralModel model, ElementList elements, ParameterSet parameters, HarmonicBalanceOptions options);
  // On a system built elsewhere, at its nominal values.
  explicit HarmonicBalance(std::shared_ptr<const HarmonicBalanceSystem> system);

  const HarmonicBalanceSystem& system() const { return *system_; }
  const std::shared_ptr<const HarmonicBalanceSystem>& shared_system() const { return system_; }
  // The parameters' names and this evaluator's values.
  const ParameterSet& parameters() const { return parameters_; }
  const ParameterValues& parameter_values() const { return parameters_.values(); }
  // Sets one value of this evaluator (throws std::out_of_range for a bad index).
  void set_parameter(int index, double value);
  // A new evaluator on the same system, with one value changed.
  HarmonicBalance with_parameter(int index, double value) const;

  int unknowns() const { return system_->unknowns(); }
  int retained_dofs() const { return system_->retained_dofs(); }
  const std::vector<int>& retained() const { return system_->retained(); }
  const FourierBasis& basis() const { return system_->basis(); }
  const StructuralModel& model() const { return system_->model(); }
  const ElementList& elements() const { return system_->elements(); }
  void refuse_residual_elements(const std::string& analysis) const { system_->refuse_residual_elements(analysis); }
  const HarmonicBalanceOptions& options() const { return system_->options(); }
  std::string condensation_method() const { return system_->condensation_method(); }
  int amplitude_parameter() const { return system_->amplitude_parameter(); }
  bool has_corners() const { return system_->has_corners(); }
  double fundamental(double omega) const { return system_->fundamental(omega); }
  int subharmonic() const { return system_->subharmonic(); }

  // HarmonicBalanceSystem's evaluations at this evaluator's values, in its workspace.
  void evaluate(const Eigen::VectorXd& x, double omega, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian = nullptr,
                Eigen::VectorXd* r_omega = nullptr) {
    system_->evaluate(values(), workspace_, x, omega, r, jacobian, r_omega);
  }
  Eigen::VectorXd parameter_derivative(const Eigen::VectorXd& x, double omega, int parameter) {
    return system_->parameter_derivative(values(), workspace_, x, omega, parameter);
  }
  Eigen::VectorXd expand(const Eigen::VectorXd& x, double omega) { return system_->expand(values(), workspace_, x, omega); }
  Eigen::VectorXd linear_solution(double omega) { return system_->linear_solution(values(), workspace_, omega); }
  Eigen::VectorXd rest_linearized_solution(double omega) { return system_->rest_linearized_solution(values(), workspace_, omega); }
  Eigen::VectorXd nonlinear_forces(const Eigen::VectorXd& x, double omega) {
    return system_->nonlinear_forces(values(), workspace_, x, omega);
  }
  std::vector<Eigen::MatrixXd> element_force_samples(const Eigen::VectorXd& x, double omega) {
    return system_->element_force_samples(values(), workspace_, x, omega);
  }
  double nonlinear_adjoint_products(const Eigen::VectorXd& x, double omega, const Eigen::VectorXd& w,
                                    Eigen::VectorXd& jacobian_transpose_w) {
    return system_->nonlinear_adjoint_products(values(), workspace_, x, omega, w, jacobian_transpose_w);
  }
  Eigen::VectorXd linear_omega_derivative(const Eigen::VectorXd& d, double omega) {
    return system_->linear_omega_derivative(workspace_, d, omega);
  }
  void hill_matrices(const Eigen::VectorXd& x, double omega, Eigen::MatrixXd& jacobian, Eigen::MatrixXd& damping) {
    system_->hill_matrices(values(), workspace_, x, omega, jacobian, damping);
  }
  void hill_element_blocks(const Eigen::VectorXd& x, double omega, const std::vector<int>& coupled, Eigen::MatrixXd& jacobian,
                           Eigen::MatrixXd& damping) {
    system_->hill_element_blocks(values(), workspace_, x, omega, coupled, jacobian, damping);
  }

 private:
  const ParameterValues& values() const { return parameters_.values(); }
  std::shared_ptr<const HarmonicBalanceSystem> system_;
  ParameterSet parameters_;
  HarmonicBalanceWorkspace workspace_;
};

}  // namespace hbtrack
