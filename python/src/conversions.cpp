// Results into Python objects: JSON documents, in-memory CSV tables.
#include <nlohmann/json.hpp>

#include "bindings.hpp"
#include "gil_release.hpp"

namespace hbtrack::python {

py::object to_python(const nlohmann::json& document) {
  // Through the json module: the dump keeps every double's 17 digits, so the numbers are the
  // ones summary.json holds.
  return py::module_::import("json").attr("loads")(document.dump());
}

nlohmann::json from_python(const py::handle& object) {
  const py::object as_number = py::module_::import("builtins").attr("float");
  const std::string text = py::module_::import("json").attr("dumps")(object, py::arg("default") = as_number).cast<std::string>();
  return nlohmann::json::parse(text);
}

py::dict Table::columns() const {
  py::dict out;
  for (size_t j = 0; j < header.size(); ++j) {
    py::array_t<double> column(static_cast<py::ssize_t>(rows.size()));
    auto values = column.mutable_unchecked<1>();
    for (size_t i = 0; i < rows.size(); ++i) values(static_cast<py::ssize_t>(i)) = rows[i][j];
    out[py::str(header[j])] = column;
  }
  return out;
}

py::array_t<double> Table::matrix() const {
  py::array_t<double> out({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(header.size())});
  auto values = out.mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < header.size(); ++j) values(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = rows[i][j];
  return out;
}

bool python_interrupted() {
  // Taking the GIL while the interpreter exits would end this thread inside the computation.
  if (interpreter_exiting()) return true;
  py::gil_scoped_acquire acquire;
  return PyErr_CheckSignals() != 0;  // leaves KeyboardInterrupt set for the caller to raise
}

}  // namespace hbtrack::python
