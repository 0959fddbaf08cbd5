#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

std::vector<double> NonlinearElement::property_values(const ParameterSet& parameters) const {
  std::vector<double> values(properties.size());
  for (size_t i = 0; i < properties.size(); ++i) values[i] = properties[i].value(parameters);
  return values;
}

}  // namespace hbtrack
