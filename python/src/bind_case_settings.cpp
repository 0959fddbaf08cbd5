// One name per option: `case.continuation` is the case file's [continuation] section, all its
// keys (the frequency range and length scale as well as the arc-length settings), as a view
// into the case. `case.nfrc`, the C++ struct's name for the same settings, stays one release
// as a deprecated alias. with_overrides: the case file's `--set` on a case already read.
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::python {

namespace {

// The [continuation] section of one case: reads and writes go to the case (kept alive by it).
struct ContinuationSection {
  CaseDefinition* c;
};

// In the case file's order (docs/case-file.md).
const std::vector<std::string> kContinuationKeys{"omega_start",
                                                 "omega_end",
                                                 "step",
                                                 "step_min",
                                                 "step_max",
                                                 "max_points",
                                                 "max_iterations",
                                                 "target_iterations",
                                                 "tolerance",
                                                 "reuse_factorization",
                                                 "contraction",
                                                 "max_angle",
                                                 "target_angle",
                                                 "predictor",
                                                 "corrector",
                                                 "length_scale",
                                                 "wall_time_limit",
                                                 "locate"};

template <class T>
void range_key(py::class_<ContinuationSection>& cls, const char* name, T NfrcOptions::*member) {
  cls.def_property(
      name, [member](const ContinuationSection& s) { return s.c->nfrc.*member; },
      [member](ContinuationSection& s, const T& value) { s.c->nfrc.*member = value; });
}

template <class T>
void step_key(py::class_<ContinuationSection>& cls, const char* name, T ContinuationOptions::*member) {
  cls.def_property(
      name, [member](const ContinuationSection& s) { return s.c->nfrc.continuation.*member; },
      [member](ContinuationSection& s, const T& value) { s.c->nfrc.continuation.*member = value; });
}

void warn_nfrc_deprecated() {
  if (PyErr_WarnEx(PyExc_DeprecationWarning,
                   "Case.nfrc is deprecated (removed in the next release): the case file's names are case.continuation "
                   "(omega_start, omega_end, length_scale, step, ...) and case.stability",
                   1) < 0)
    throw py::error_already_set();
}

}  // namespace

void bind_case_settings(py::module_& m, py::class_<CaseDefinition>& case_class) {
  py::class_<ContinuationSection> section(m, "ContinuationSection",
                                          "The case file's [continuation] section of a Case: every key, read and written "
                                          "in place (case.continuation.omega_start = 0.5).");
  range_key(section, "omega_start", &NfrcOptions::omega_start);
  range_key(section, "omega_end", &NfrcOptions::omega_end);
  range_key(section, "length_scale", &NfrcOptions::length_scale);
  step_key(section, "step", &ContinuationOptions::step);
  step_key(section, "step_min", &ContinuationOptions::step_min);
  step_key(section, "step_max", &ContinuationOptions::step_max);
  step_key(section, "max_points", &ContinuationOptions::max_points);
  step_key(section, "max_iterations", &ContinuationOptions::max_iterations);
  step_key(section, "target_iterations", &ContinuationOptions::target_iterations);
  step_key(section, "tolerance", &ContinuationOptions::tolerance);
  step_key(section, "reuse_factorization", &ContinuationOptions::reuse_factorization);
  step_key(section, "contraction", &ContinuationOptions::contraction);
  step_key(section, "max_angle", &ContinuationOptions::max_angle);
  step_key(section, "target_angle", &ContinuationOptions::target_angle);
  step_key(section, "predictor", &ContinuationOptions::predictor);
  step_key(section, "corrector", &ContinuationOptions::corrector);
  step_key(section, "wall_time_limit", &ContinuationOptions::wall_time_limit);
  step_key(section, "locate", &ContinuationOptions::locate);
  section.def_property_readonly_static("fields", [](const py::object&) { return kContinuationKeys; })
      .def("__repr__", [](const py::object& self) { return options_repr(self, kContinuationKeys); })
      .def("__eq__",
           [](const ContinuationSection& a, const py::object& other) {
             if (!py::isinstance<ContinuationSection>(other)) return false;
             const py::object self = py::cast(a);
             for (const std::string& key : kContinuationKeys)
               if (!self.attr(key.c_str()).equal(other.attr(key.c_str()))) return false;
             return true;
           })
      .def(
          "validate", [](const ContinuationSection& s) { s.c->nfrc.validate(); }, "raises ValueError naming the field and the rule broken")
      .def_property_readonly(
          "options", [](const ContinuationSection& s) -> ContinuationOptions& { return s.c->nfrc.continuation; },
          py::return_value_policy::reference_internal, "the arc-length settings alone (ContinuationOptions), shared with the case");

  case_class
      .def_property("continuation", py::cpp_function([](CaseDefinition& c) { return ContinuationSection{&c}; }, py::keep_alive<0, 1>()),
                    py::cpp_function([](CaseDefinition& c, const py::object& value) {
                      // A section (of this or another case) sets every key; ContinuationOptions the
                      // arc-length settings, keeping the frequency range.
                      if (py::isinstance<ContinuationSection>(value)) {
                        const CaseDefinition* other = value.cast<const ContinuationSection&>().c;
                        const StabilityOptions stability = c.nfrc.stability;
                        c.nfrc = other->nfrc;
                        c.nfrc.stability = stability;
                      } else {
                        c.nfrc.continuation = value.cast<ContinuationOptions>();
                      }
                    }),
                    "the case file's [continuation] section: omega_start, omega_end, length_scale, step, ... (ContinuationSection)")
      .def_property("nfrc",
                    py::cpp_function(
                        [](CaseDefinition& c) -> NfrcOptions& {
                          warn_nfrc_deprecated();
                          return c.nfrc;
                        },
                        py::return_value_policy::reference_internal),
                    py::cpp_function([](CaseDefinition& c, const NfrcOptions& o) {
                      warn_nfrc_deprecated();
                      c.nfrc = o;
                    }),
                    "deprecated: case.continuation and case.stability");
  m.def("with_overrides", &with_overrides, py::arg("case"), py::arg("overrides"),
        "a copy of the case with NAME=VALUE overrides of its parameters and settings (as --set)");
}

}  // namespace hbtrack::python
