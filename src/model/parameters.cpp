#include "hbtrack/model/parameters.hpp"

#include <stdexcept>

namespace hbtrack {

int ParameterSet::set(const std::string& name, double value) {
  const int i = find(name);
  if (i >= 0) {
    values_[static_cast<size_t>(i)] = value;
    return i;
  }
  names_.push_back(name);
  values_.push_back(value);
  return size() - 1;
}

int ParameterSet::find(const std::string& name) const {
  for (size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return static_cast<int>(i);
  return -1;
}

void ParameterSet::fix(int index, const std::string& reason) {
  if (index < 0 || index >= size()) throw std::out_of_range("parameter index out of range");
  for (auto& [i, why] : fixed_)
    if (i == index) {
      why = reason;
      return;
    }
  fixed_.emplace_back(index, reason);
}

std::string ParameterSet::fixed_reason(int index) const {
  for (const auto& [i, why] : fixed_)
    if (i == index) return why;
  return "";
}

double ParameterSet::value(const std::string& name) const {
  const int i = find(name);
  if (i < 0) throw std::out_of_range("unknown parameter '" + name + "'");
  return values_[static_cast<size_t>(i)];
}

}  // namespace hbtrack
