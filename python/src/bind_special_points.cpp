// Which special point of an earlier result a run starts from (hbtrack/runs/special_point_start.hpp):
// the same choice and the same errors as the CLI's --lp/--ns/--pd/--point, and the names of the
// types from their one table (python/hbtrack/special_points.py checks its own against them).
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "hbtrack/runs/special_point_start.hpp"

namespace hbtrack::python {

namespace {

template <class Type>
std::vector<std::string> names_of() {
  std::vector<std::string> names;
  for (const ChoiceName<Type>& entry : ChoiceTable<Type>::names) names.emplace_back(entry.name);
  return names;
}

size_t special_point_index(const py::handle& special_points, SpecialPointType type, long k, const std::string& keyword,
                           const std::string& source) {
  return runs::special_point_index(from_python(special_points), type, k, {keyword, source});
}

py::dict switch_point(const py::handle& special_points, long point, size_t state_rows, const std::string& keyword,
                      const std::string& source) {
  const runs::SwitchPoint s = runs::switch_point(from_python(special_points), point, state_rows, {keyword, source});
  py::dict out;
  out["type"] = to_string(s.type);
  out["special_row"] = s.special_row;
  out["before_row"] = s.before_row;
  out["after_row"] = s.after_row;
  return out;
}

}  // namespace

void bind_special_points(py::module_& m) {
  m.def("special_point_type_names", &names_of<SpecialPointType>, "the names of a branch's special point types, in table order");
  m.def("curve_extremum_type_names", &names_of<CurveExtremumType>, "the names of a tracking curve's special point types");
  m.def("special_point_index", &special_point_index, py::arg("special_points"), py::arg("type"), py::arg("k"), py::arg("keyword"),
        py::arg("source"),
        "the index into special_points (the row of special_states) of the k-th point of `type`, counted from 1 in increasing omega");
  m.def("switch_point", &switch_point, py::arg("special_points"), py::arg("point"), py::arg("state_rows"), py::arg("keyword"),
        py::arg("source"), "switch's point (a BP or a PD): {type, special_row, before_row, after_row}");
}

}  // namespace hbtrack::python
