#include "hbtrack/timeint/equation_of_motion.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbtrack {

EquationOfMotion::EquationOfMotion(const StructuralModel& model, const ElementList& elements, const ParameterSet& parameters, double omega)
    : mass_(model.mass), damping_(model.damping), stiffness_(model.stiffness), omega_(omega) {
  model.validate();
  if (!(omega > 0) || !std::isfinite(omega)) throw std::invalid_argument("omega: must be > 0 and finite, got " + std::to_string(omega));
  int history_size_so_far = 0;
  const int amplitude_index = parameters.find("amplitude");
  // A forcing that grows with the frequency is fixed at this simulation's omega.
  const double amplitude = (amplitude_index < 0 ? 1.0 : parameters.value(amplitude_index)) * model.forcing_growth.factor(omega);
  for (const HarmonicForce& h : model.forcing) forcing_.push_back({h.order, amplitude * h.cos_part, amplitude * h.sin_part});

  for (const auto& element : elements) {
    if (element->properties.size() != element->property_names().size())
      throw std::invalid_argument("element " + element->type() + ": property count does not match");
    if (element->uses_linear_residual())
      throw std::invalid_argument("element " + element->type() +
                                  " takes its forces from the harmonic-balance residual (law = \"dlft\"): time integration needs a "
                                  "time-domain law (law = \"penalty\")");
    if (element->history_dependent() && element->history_state_size() == 0)
      throw std::invalid_argument("element " + element->type() + " has no time-stepping form: time integration does not support it");
    for (int d : element->dofs)
      if (d < 0 || d >= model.dofs()) throw std::invalid_argument("element " + element->type() + ": dof index out of range");
    ElementSlot slot;
    slot.element = element;
    slot.property_values = element->property_values(parameters);
    slot.x.resize(1, element->local_dofs());
    slot.v.resize(1, element->local_dofs());
    slot.history_offset = history_size_so_far;
    slot.history_count = element->history_dependent() ? element->history_state_size() : 0;
    history_size_so_far += slot.history_count;
    slot.switching = element->switching_surfaces(slot.property_values);
    switching_count_ += slot.switching;
    elements_.push_back(std::move(slot));
  }
  history_ = Eigen::VectorXd::Zero(history_size_so_far);
}

void EquationOfMotion::start_history(double time, const Eigen::VectorXd& history) {
  if (history.size() != 0 && history.size() != history_.size())
    throw std::invalid_argument("EquationOfMotion::start_history: expected " + std::to_string(history_.size()) +
                                " internal variables, got " + std::to_string(history.size()));
  history_ = history.size() ? history : Eigen::VectorXd::Zero(history_.size());
  history_time_ = time;
}

void EquationOfMotion::gather(ElementSlot& s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  for (int i = 0; i < s.element->local_dofs(); ++i) {
    s.x(0, i) = x(s.element->dofs[static_cast<size_t>(i)]);
    s.v(0, i) = v(s.element->dofs[static_cast<size_t>(i)]);
  }
}

void EquationOfMotion::commit_history(double time, const Eigen::VectorXd& x) {
  for (ElementSlot& s : elements_) {
    if (s.history_count == 0) continue;
    gather(s, x, x);
    s.element->history_step(s.x, history_.segment(s.history_offset, s.history_count), time - history_time_, omega_, s.property_values,
                            s.step);
    history_.segment(s.history_offset, s.history_count) = s.step.state;
  }
  history_time_ = time;
}

Eigen::VectorXd EquationOfMotion::periodic_history(const Eigen::MatrixXd& period_samples) const {
  Eigen::VectorXd out(history_.size());
  for (const ElementSlot& s : elements_) {
    if (s.history_count == 0) continue;
    Eigen::MatrixXd local(period_samples.rows(), s.element->local_dofs());
    for (int i = 0; i < s.element->local_dofs(); ++i) local.col(i) = period_samples.col(s.element->dofs[static_cast<size_t>(i)]);
    out.segment(s.history_offset, s.history_count) = s.element->periodic_history(local, omega_, s.property_values).row(0).transpose();
  }
  return out;
}

double EquationOfMotion::period() const { return 2.0 * std::numbers::pi / omega_; }

void EquationOfMotion::external_force(double t, Eigen::VectorXd& f) const {
  f.setZero(dofs());
  for (const ScaledForce& h : forcing_) {
    if (h.order == 0) {
      f += h.cos_part;
      continue;
    }
    const double phase = h.order * omega_ * t;
    f += std::cos(phase) * h.cos_part + std::sin(phase) * h.sin_part;
  }
}

void EquationOfMotion::nonlinear_force(double time, const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& f,
                                       Eigen::MatrixXd* df_dx, Eigen::MatrixXd* df_dv) {
  const int n = dofs();
  f.setZero(n);
  if (df_dx) df_dx->setZero(n, n);
  if (df_dv) df_dv->setZero(n, n);
  for (ElementSlot& s : elements_) {
    const NonlinearElement& element = *s.element;
    const int k = element.local_dofs();
    gather(s, x, v);
    if (s.history_count > 0) {
      element.history_step(s.x, history_.segment(s.history_offset, s.history_count), time - history_time_, omega_, s.property_values,
                           s.step);
      for (int i = 0; i < k; ++i) {
        const int row = element.dofs[static_cast<size_t>(i)];
        f(row) += s.step.force(i);
        if (df_dx)
          for (int j = 0; j < k; ++j) (*df_dx)(row, element.dofs[static_cast<size_t>(j)]) += s.step.dforce_dx(i, j);
      }
      continue;
    }
    element.evaluate(s.x, s.v, omega_, s.property_values, s.response, false);
    const ElementResponse& r = s.response;
    for (int i = 0; i < k; ++i) {
      const int row = element.dofs[static_cast<size_t>(i)];
      f(row) += r.force(0, i);
      for (int j = 0; j < k; ++j) {
        const int col = element.dofs[static_cast<size_t>(j)];
        if (df_dx) (*df_dx)(row, col) += r.dforce_dx(0, i + k * j);
        // Elements that ignore velocity leave dforce_dv empty.
        if (df_dv && r.dforce_dv.size() > 0) (*df_dv)(row, col) += r.dforce_dv(0, i + k * j);
      }
    }
  }
}

void EquationOfMotion::switching_values(const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& out) {
  out.resize(switching_count_);
  int next = 0;
  for (ElementSlot& s : elements_) {
    if (s.switching == 0) continue;
    gather(s, x, v);
    s.element->switching_values(s.x, s.v, s.property_values, out.data() + next);
    next += s.switching;
  }
}

}  // namespace hbtrack
