#pragma once
// Named scalar parameters of a study (`amplitude`, `mu`, `clearance`, any user name) and the
// binding of an element property to one of them: value = offset + scale * parameter.
#include <string>
#include <vector>

namespace hbtrack {

// Values of a ParameterSet's parameters, in its order: what an evaluation depends on besides
// the unknowns (HarmonicBalanceSystem takes them explicitly).
using ParameterValues = std::vector<double>;

class ParameterSet {
 public:
  // Adds a parameter or, when the name exists, overwrites its value. Returns its index.
  int set(const std::string& name, double value);
  int find(const std::string& name) const;  // -1 when absent
  double value(int index) const { return values_[static_cast<size_t>(index)]; }
  double& value(int index) { return values_[static_cast<size_t>(index)]; }
  double value(const std::string& name) const;  // throws std::out_of_range
  const ParameterValues& values() const { return values_; }
  const std::vector<std::string>& names() const { return names_; }
  int size() const { return static_cast<int>(names_.size()); }
  // A parameter the model's matrices were built with (the rotation speed of K(Omega)): no
  // continuation may vary it. `reason` completes "'NAME' ..." in the error of those that try.
  void fix(int index, const std::string& reason);
  // The reason it is fixed, "" when it is free.
  std::string fixed_reason(int index) const;

 private:
  std::vector<std::string> names_;
  ParameterValues values_;
  std::vector<std::pair<int, std::string>> fixed_;
};

// A property of an element: a constant, or an affine function of one named parameter.
struct ParameterBinding {
  double offset = 0.0;
  double scale = 0.0;
  int parameter = -1;  // index in the ParameterSet, -1 for a constant (= offset)

  static ParameterBinding constant(double v) { return {v, 0.0, -1}; }
  static ParameterBinding linked(int index, double scale_ = 1.0, double offset_ = 0.0) { return {offset_, scale_, index}; }
  double value(const ParameterValues& p) const { return parameter < 0 ? offset : offset + scale * p[static_cast<size_t>(parameter)]; }
  double value(const ParameterSet& p) const { return value(p.values()); }
  // d value / d parameter `index`.
  double derivative(int index) const { return parameter == index ? scale : 0.0; }
};

}  // namespace hbtrack
