#include "hbtrack/elements/nonlinear_element.hpp"

#include <cstdio>
#include <stdexcept>

namespace hbtrack {

std::vector<double> NonlinearElement::property_values(const ParameterValues& parameters) const {
  std::vector<double> values(properties.size());
  for (size_t i = 0; i < properties.size(); ++i) values[i] = properties[i].value(parameters);
  return values;
}

void NonlinearElement::history_step(const Eigen::MatrixXd&, const Eigen::VectorXd&, double, double, const std::vector<double>&,
                                    HistoryStep&) const {
  throw std::logic_error("element " + type() + " has no time-stepping form");
}

void NonlinearElement::evaluate_with_residual(const Eigen::MatrixXd&, const Eigen::MatrixXd&, double, const std::vector<double>&,
                                              ElementResponse&, bool) const {
  throw std::logic_error("element " + type() + " does not read the linear residual");
}

std::string exact_text(const Eigen::Ref<const Eigen::VectorXd>& values) {
  std::string text;
  char number[40];
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    std::snprintf(number, sizeof number, "%s%a", i ? "," : "", values(i));
    text += number;
  }
  return text;
}

Eigen::MatrixXd history_sensitivity_matrix(const ElementResponse& response, Eigen::Index samples, int dofs) {
  const Eigen::Index size = samples * dofs;
  if (response.history_operator) return response.history_operator->apply(Eigen::MatrixXd::Identity(size, size));
  return Eigen::MatrixXd(response.history_dforce_dx);
}

Eigen::MatrixXd NonlinearElement::periodic_history(const Eigen::MatrixXd& x, double, const std::vector<double>&) const {
  return Eigen::MatrixXd(x.rows(), 0);
}

}  // namespace hbtrack
