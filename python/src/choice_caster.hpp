#pragma once
// The settings' choices (hbtrack/util/choices.hpp) cross into Python as their names, the case
// file's: a str out, a str parsed in. An unknown name raises ValueError with the choice's message
// ("continuation.predictor: must be tangent or secant, got 'euler'") where it is assigned.
// Every binding file sees this caster (through bindings.hpp), so no enum is bound twice.
#include <pybind11/pybind11.h>

#include <string>

#include "hbtrack/util/choices.hpp"

namespace pybind11::detail {

template <hbtrack::NamedChoice Choice>
class type_caster<Choice> {
 public:
  PYBIND11_TYPE_CASTER(Choice, const_name("str"));

  bool load(handle source, bool /*convert*/) {
    if (!isinstance<str>(source)) return false;
    value = hbtrack::parse_choice<Choice>(source.cast<std::string>());
    return true;
  }
  static handle cast(Choice choice, return_value_policy /*policy*/, handle /*parent*/) { return str(hbtrack::to_string(choice)).release(); }
};

}  // namespace pybind11::detail
