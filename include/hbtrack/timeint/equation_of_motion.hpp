#pragma once
// The full (uncondensed) equation of motion in the time domain, for time integration:
//   M x'' + C x' + K x + f_nl(x, x', omega) = f_ext(t),
//   f_ext(t) = amplitude * g(w) * sum over the model's forcing of (cos_part cos(h w t) + sin_part sin(h w t))
// with g(w) = (w / w_ref)^k the model's forcing growth (1 for a fixed forcing)
// (order 0: cos_part is the constant load). f_nl is the sum of the case's elements evaluated one
// instant at a time (N = 1 sample of their local dofs); Lanczos filtering acts on harmonics and
// has no meaning here. Elements see omega only through tip_contact's rotation speed
// W = engine_order * omega + rotation_speed, so they get the forcing frequency.
// History elements (friction sliders) carry internal variables from step to step: the equation
// holds their committed values, every force evaluation return-maps from them to the trial
// displacement (NonlinearElement::history_step), and an integrator commits the displacement it
// accepts at the end of each step. Within a step the variables are thus frozen at the step's
// start, exact for a rate-independent law when d moves monotonically over the step.
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/elements/nonlinear_element.hpp"
#include "hbtrack/model/parameters.hpp"
#include "hbtrack/model/structural_model.hpp"

namespace hbtrack {

class EquationOfMotion {
 public:
  // Parameters are read once: element property values and `amplitude` (1 when absent) stay
  // fixed during a simulation. Throws std::invalid_argument on a bad model, element or omega.
  EquationOfMotion(const StructuralModel& model, const ElementList& elements, const ParameterSet& parameters, double omega);

  int dofs() const { return static_cast<int>(mass_.rows()); }
  double omega() const { return omega_; }
  double period() const;
  const Eigen::MatrixXd& mass() const { return mass_; }
  const Eigen::MatrixXd& damping() const { return damping_; }
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }
  bool has_nonlinear_elements() const { return !elements_.empty(); }

  // f = f_ext(t).
  void external_force(double t, Eigen::VectorXd& f) const;
  // f = f_nl(x, v) at `time` (history elements step from their committed state to x); when
  // given, also the n x n tangents df/dx and df/dv (overwritten).
  // Not const: reuses per-element buffers (one instance per thread).
  void nonlinear_force(double time, const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& f,
                       Eigen::MatrixXd* df_dx = nullptr, Eigen::MatrixXd* df_dv = nullptr);
  // The elements' switching surfaces (NonlinearElement::switching_values): where the tangents
  // jump, so that a stepper can stop on them. `out` gets switching_count() values.
  int switching_count() const { return switching_count_; }
  void switching_values(const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& out);

  // The history elements' internal variables, concatenated in element order.
  int history_size() const { return static_cast<int>(history_.size()); }
  const Eigen::VectorXd& history() const { return history_; }
  // Sets them at `time` (empty: rest, all zero).
  void start_history(double time, const Eigen::VectorXd& history);
  // Accepts x at `time` as the end of a step: the history elements step to it and keep the result.
  void commit_history(double time, const Eigen::VectorXd& x);
  // The internal variables at the first sample of a periodic motion given by N samples of one
  // period (N x dofs): the elements' periodic steady state, as the harmonic balance sees it.
  Eigen::VectorXd periodic_history(const Eigen::MatrixXd& period_samples) const;

 private:
  struct ElementSlot {
    std::shared_ptr<NonlinearElement> element;
    std::vector<double> property_values;
    Eigen::MatrixXd x, v;  // 1 x k: one time sample of the local dofs
    ElementResponse response;
    int history_offset = 0, history_count = 0;  // its internal variables within history_
    HistoryStep step;
    int switching = 0;  // the element's switching surfaces
  };
  void gather(ElementSlot& slot, const Eigen::VectorXd& x, const Eigen::VectorXd& v) const;
  struct ScaledForce {
    int order = 1;
    Eigen::VectorXd cos_part, sin_part;  // already multiplied by amplitude
  };

  Eigen::MatrixXd mass_, damping_, stiffness_;
  std::vector<ScaledForce> forcing_;
  std::vector<ElementSlot> elements_;
  double omega_;
  Eigen::VectorXd history_;  // committed internal variables of the history elements
  double history_time_ = 0;  // when they were committed
  int switching_count_ = 0;
};

}  // namespace hbtrack
