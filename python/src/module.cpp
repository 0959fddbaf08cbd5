// The _hbtrack extension: C++ exceptions become Python ones, then each folder's bindings.
#include <stdexcept>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_hbtrack, m) {
  m.doc() = "hbtrack's compiled core; use the hbtrack package, not this module";
  // Bad input (a case file, an override, an option value) is a ValueError whose message names
  // the field, as the CLI's one-line errors do; failures of a run stay RuntimeError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const hbtrack::CaseError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  hbtrack::python::bind_options(m);
  hbtrack::python::bind_case(m);
  hbtrack::python::bind_hbm(m);
  hbtrack::python::bind_analysis(m);
  hbtrack::python::bind_timeint(m);
  hbtrack::python::bind_model(m);
  hbtrack::python::bind_continuation(m);
  hbtrack::python::bind_switch(m);
  hbtrack::python::bind_special_points(m);
  hbtrack::python::bind_elements(m);
}
