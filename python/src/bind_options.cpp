// Option structs as Python classes: attribute names are the C++ fields, which are also the case
// file's keys and the CLI's flags. Keyword construction, repr and validate() (ValueError naming
// the field) come with every class.
#include <pybind11/stl.h>

#include <algorithm>

#include "bindings.hpp"
#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/timeint/steady_state.hpp"

namespace hbtrack::python {

// ClassName(field=value, ...) with Python's repr of each value.
std::string options_repr(const py::object& self, const std::vector<std::string>& fields) {
  std::string text = py::str(py::type::of(self).attr("__name__"));
  text += "(";
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i) text += ", ";
    text += fields[i];
    text += "=";
    text += py::repr(self.attr(fields[i].c_str())).cast<std::string>();
  }
  return text + ")";
}

namespace {

// Binds T with its fields (readwrite), a keyword constructor that rejects unknown names,
// __repr__, validate() when T has one, and `fields` (the names, in order).
template <class T>
py::class_<T> bind_options_class(py::module_& m, const char* name, const char* doc, const std::vector<std::string>& fields) {
  py::class_<T> cls(m, name, doc);
  cls.def(py::init([fields, name](const py::kwargs& kwargs) {
       T options;
       py::object self = py::cast(options);
       for (const auto& [key, value] : kwargs) {
         const std::string field = py::str(key);
         if (std::find(fields.begin(), fields.end(), field) == fields.end()) {
           std::string known;
           for (const std::string& f : fields) known += (known.empty() ? "" : ", ") + f;
           std::string message = name;
           message += ": unknown option '";
           message += field;
           message += "' (known: ";
           message += known;
           message += ")";
           throw py::type_error(message);
         }
         self.attr(field.c_str()) = value;
       }
       return self.cast<T>();
     }))
      .def("__repr__", [fields](const py::object& self) { return options_repr(self, fields); })
      .def("__eq__",
           [fields](const py::object& self, const py::object& other) {
             if (!py::type::of(self).is(py::type::of(other))) return false;
             for (const std::string& f : fields)
               if (!self.attr(f.c_str()).equal(other.attr(f.c_str()))) return false;
             return true;
           })
      .def_property_readonly_static("fields", [fields](const py::object&) { return fields; });
  if constexpr (requires(const T& t) { t.validate(); })
    cls.def("validate", &T::validate, "raises ValueError naming the field and the rule broken");
  return cls;
}

}  // namespace

void bind_options(py::module_& m) {
  bind_options_class<ContinuationOptions>(
      m, "ContinuationOptions", "Arc-length continuation settings (case file [continuation]).",
      {"step", "step_min", "step_max", "max_points", "max_iterations", "target_iterations", "tolerance", "max_angle", "target_angle",
       "predictor", "corrector", "wall_time_limit", "locate", "reuse_factorization", "contraction"})
      .def_readwrite("step", &ContinuationOptions::step)
      .def_readwrite("step_min", &ContinuationOptions::step_min)
      .def_readwrite("step_max", &ContinuationOptions::step_max)
      .def_readwrite("max_points", &ContinuationOptions::max_points)
      .def_readwrite("max_iterations", &ContinuationOptions::max_iterations)
      .def_readwrite("target_iterations", &ContinuationOptions::target_iterations)
      .def_readwrite("tolerance", &ContinuationOptions::tolerance)
      .def_readwrite("max_angle", &ContinuationOptions::max_angle)
      .def_readwrite("target_angle", &ContinuationOptions::target_angle)
      .def_readwrite("predictor", &ContinuationOptions::predictor)
      .def_readwrite("corrector", &ContinuationOptions::corrector)
      .def_readwrite("wall_time_limit", &ContinuationOptions::wall_time_limit)
      .def_readwrite("locate", &ContinuationOptions::locate)
      .def_readwrite("reuse_factorization", &ContinuationOptions::reuse_factorization)
      .def_readwrite("contraction", &ContinuationOptions::contraction);
  bind_options_class<StabilityOptions>(m, "StabilityOptions", "Floquet stability settings (case file [stability]).",
                                       {"method", "monodromy_steps", "hill_solver", "cross_check", "every_point"})
      .def_readwrite("method", &StabilityOptions::method)
      .def_readwrite("monodromy_steps", &StabilityOptions::monodromy_steps)
      .def_readwrite("hill_solver", &StabilityOptions::hill_solver)
      .def_readwrite("cross_check", &StabilityOptions::cross_check)
      .def_readwrite("every_point", &StabilityOptions::every_point);
  bind_options_class<AdaptiveHarmonics>(m, "AdaptiveHarmonics",
                                        "Harmonics chosen as frc goes (case file harmonic_balance.adaptive): H within [min, max], "
                                        "one more above add_above, fewer below drop_below; max = 0: off.",
                                        {"min", "max", "add_above", "drop_below"})
      .def_readwrite("min", &AdaptiveHarmonics::min)
      .def_readwrite("max", &AdaptiveHarmonics::max)
      .def_readwrite("add_above", &AdaptiveHarmonics::add_above)
      .def_readwrite("drop_below", &AdaptiveHarmonics::drop_below);
  bind_options_class<HarmonicBalanceOptions>(m, "HarmonicBalanceOptions", "Harmonic balance settings (case file [harmonic_balance]).",
                                             {"harmonics", "subharmonic", "samples", "condensation", "adaptive"})
      // H, or the list of harmonics balanced ([1, 3, 5]: harmonic_balance.harmonics as a list).
      .def_property(
          "harmonics",
          [](const HarmonicBalanceOptions& o) -> py::object {
            if (o.harmonic_list.empty()) return py::int_(o.harmonics);
            return py::cast(o.harmonic_list);
          },
          [](HarmonicBalanceOptions& o, const py::object& value) {
            if (py::isinstance<py::int_>(value)) {
              o.harmonic_list.clear();
              o.harmonics = value.cast<int>();
            } else {
              const auto list = value.cast<std::vector<int>>();
              if (list.empty())
                throw py::value_error("harmonic_balance.harmonics: an empty list (give H, or the harmonics to balance, e.g. [1, 3, 5])");
              o.harmonic_list = list;
              o.harmonics = list.back();
              o.validate();  // a bad list is refused here, naming the rule
              o.select(list);
            }
          })
      .def_readwrite("subharmonic", &HarmonicBalanceOptions::subharmonic)
      .def_readwrite("samples", &HarmonicBalanceOptions::samples)
      .def_readwrite("condensation", &HarmonicBalanceOptions::condensation)
      .def_readwrite("adaptive", &HarmonicBalanceOptions::adaptive);
  bind_options_class<NfrcOptions>(m, "NfrcOptions",
                                  "NFRC settings: frequency range (rad/s) and length scale (case file [continuation]), "
                                  "continuation and stability.",
                                  {"omega_start", "omega_end", "length_scale", "continuation", "stability"})
      .def_readwrite("omega_start", &NfrcOptions::omega_start)
      .def_readwrite("omega_end", &NfrcOptions::omega_end)
      .def_readwrite("length_scale", &NfrcOptions::length_scale)
      .def_readwrite("continuation", &NfrcOptions::continuation)
      .def_readwrite("stability", &NfrcOptions::stability);
  bind_options_class<FoldTrackingOptions>(m, "FoldTrackingOptions",
                                          "Limit-point tracking settings: method (bordered | extended) and the parameter's "
                                          "interval (hbtrack track --method, --range).",
                                          {"method", "parameter_min", "parameter_max", "continuation"})
      .def_readwrite("method", &FoldTrackingOptions::method)
      .def_readwrite("parameter_min", &FoldTrackingOptions::parameter_min)
      .def_readwrite("parameter_max", &FoldTrackingOptions::parameter_max)
      .def_readwrite("continuation", &FoldTrackingOptions::continuation);
  bind_options_class<SteadyStateOptions>(m, "SteadyStateOptions",
                                         "When a time integration has reached its periodic steady state "
                                         "(hbtrack simulate --max-periods, --record-periods).",
                                         {"tolerance", "confirmations", "max_periods", "record_periods", "harmonics"})
      .def_readwrite("tolerance", &SteadyStateOptions::tolerance)
      .def_readwrite("confirmations", &SteadyStateOptions::confirmations)
      .def_readwrite("max_periods", &SteadyStateOptions::max_periods)
      .def_readwrite("record_periods", &SteadyStateOptions::record_periods)
      .def_readwrite("harmonics", &SteadyStateOptions::harmonics);
}

}  // namespace hbtrack::python
