#pragma once
// Shared by the binding translation units of the _hbtrack extension: registration functions (one
// per C++ folder bound) and the conversions of results into Python objects.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "choice_caster.hpp"

namespace hbtrack {
struct CaseDefinition;
}

namespace hbtrack::python {

namespace py = pybind11;

void bind_options(py::module_& m);
void bind_case(py::module_& m);
void bind_analysis(py::module_& m);
void bind_hbm(py::module_& m);
void bind_timeint(py::module_& m);
void bind_model(py::module_& m);
void bind_continuation(py::module_& m);
void bind_switch(py::module_& m);
void bind_special_points(py::module_& m);
void bind_elements(py::module_& m);
// On the Case class: `continuation` (the case file's [continuation] section), the deprecated
// `nfrc`, and with_overrides.
void bind_case_settings(py::module_& m, py::class_<CaseDefinition>& case_class);

// summary.json as the Python json module would read it (same keys, same numbers).
py::object to_python(const nlohmann::json& document);
// A Python object of JSON types (a result's special_points, as to_python gives them or
// read_result reads them) as a JSON document; numpy scalars count as numbers.
nlohmann::json from_python(const py::handle& object);

// A table the CLI writes as CSV, kept in memory: header and rows.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  py::dict columns() const;            // {column name: 1-D float array}, as branch.csv's columns
  py::array_t<double> matrix() const;  // rows x columns, as states.csv without its header
};

// ClassName(field=value, ...) with Python's repr of each field: the options classes' repr.
std::string options_repr(const py::object& self, const std::vector<std::string>& fields);

// True (and the Python error set) when Ctrl-C arrived; callable with the GIL released.
bool python_interrupted();

}  // namespace hbtrack::python
