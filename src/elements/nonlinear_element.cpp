#include "hbtrack/elements/nonlinear_element.hpp"

#include <stdexcept>

namespace hbtrack {

std::vector<double> NonlinearElement::property_values(const ParameterSet& parameters) const {
  std::vector<double> values(properties.size());
  for (size_t i = 0; i < properties.size(); ++i) values[i] = properties[i].value(parameters);
  return values;
}

void NonlinearElement::history_step(const Eigen::MatrixXd&, const Eigen::VectorXd&, double, double, const std::vector<double>&,
                                    HistoryStep&) const {
  throw std::logic_error("element " + type() + " has no time-stepping form");
}

Eigen::MatrixXd NonlinearElement::periodic_history(const Eigen::MatrixXd& x, double, const std::vector<double>&) const {
  return Eigen::MatrixXd(x.rows(), 0);
}

}  // namespace hbtrack
