#include "hbtrack/timeint/equation_of_motion.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbtrack {

EquationOfMotion::EquationOfMotion(const StructuralModel& model, const ElementList& elements,
                                   const ParameterSet& parameters, double omega)
    : mass_(model.mass), damping_(model.damping), stiffness_(model.stiffness), omega_(omega) {
  model.validate();
  if (!(omega > 0) || !std::isfinite(omega))
    throw std::invalid_argument("omega: must be > 0 and finite, got " + std::to_string(omega));
  const int amplitude_index = parameters.find("amplitude");
  const double amplitude = amplitude_index < 0 ? 1.0 : parameters.value(amplitude_index);
  for (const HarmonicForce& h : model.forcing) forcing_.push_back({h.order, amplitude * h.cos_part, amplitude * h.sin_part});

  for (const auto& element : elements) {
    if (element->properties.size() != element->property_names().size())
      throw std::invalid_argument("element " + element->type() + ": property count does not match");
    if (element->history_dependent())
      throw std::invalid_argument("element " + element->type() + " depends on its history (a hysteresis over the period): time integration does not support it");
    for (int d : element->dofs)
      if (d < 0 || d >= model.dofs()) throw std::invalid_argument("element " + element->type() + ": dof index out of range");
    ElementSlot slot;
    slot.element = element;
    slot.property_values = element->property_values(parameters);
    slot.x.resize(1, element->local_dofs());
    slot.v.resize(1, element->local_dofs());
    slot.switching = element->switching_surfaces(slot.property_values);
    switching_count_ += slot.switching;
    elements_.push_back(std::move(slot));
  }
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

void EquationOfMotion::nonlinear_force(const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd& f,
                                       Eigen::MatrixXd* df_dx, Eigen::MatrixXd* df_dv) {
  const int n = dofs();
  f.setZero(n);
  if (df_dx) df_dx->setZero(n, n);
  if (df_dv) df_dv->setZero(n, n);
  for (ElementSlot& s : elements_) {
    const NonlinearElement& element = *s.element;
    const int k = element.local_dofs();
    gather(s, x, v);
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

void EquationOfMotion::gather(ElementSlot& s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  const auto& dofs = s.element->dofs;
  for (size_t i = 0; i < dofs.size(); ++i) {
    s.x(0, static_cast<Eigen::Index>(i)) = x(dofs[i]);
    s.v(0, static_cast<Eigen::Index>(i)) = v(dofs[i]);
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
