// Case files: load_case with overrides (the CLI's --set) and the Case object they give.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::python {

void bind_case(py::module_& m) {
  py::class_<CaseDefinition> case_class(m, "Case",
                                        "A study read from a case file: model, elements, parameters, harmonic balance, NFRC "
                                        "settings and outputs. Options are attributes named as the case file's keys.");
  case_class.def_readwrite("path", &CaseDefinition::path)
      .def_readwrite("harmonic_balance", &CaseDefinition::harmonic_balance)
      // The case file's [stability] section, which the NFRC options hold.
      .def_property(
          "stability", [](CaseDefinition& c) -> StabilityOptions& { return c.nfrc.stability; },
          [](CaseDefinition& c, const StabilityOptions& o) { c.nfrc.stability = o; }, py::return_value_policy::reference_internal)
      .def_property_readonly("dof_names", [](const CaseDefinition& c) { return c.model.dof_names; })
      .def_property_readonly("mass", [](const CaseDefinition& c) { return c.model.mass; })
      .def_property_readonly("stiffness", [](const CaseDefinition& c) { return c.model.stiffness; })
      .def_property_readonly("damping", [](const CaseDefinition& c) { return c.model.damping; })
      // The excitations beside [[forcing]], as the case file wrote them (None when absent).
      .def_property_readonly(
          "forcing_growth",
          [](const CaseDefinition& c) -> py::object {
            if (!c.model.forcing_growth.active() || c.base_motion) return py::none();
            py::dict out;
            out["exponent"] = c.model.forcing_growth.exponent;
            out["reference_frequency"] = c.model.forcing_growth.reference_frequency;
            return out;
          },
          "[forcing_growth] as {exponent, reference_frequency}: the forcing times (omega/reference_frequency)^exponent; None when fixed")
      .def_property_readonly(
          "base_motion",
          [](const CaseDefinition& c) -> py::object {
            if (!c.base_motion) return py::none();
            const BaseMotion& b = *c.base_motion;
            std::vector<std::string> dofs;
            for (int d : b.dofs) dofs.push_back(c.model.dof_names[static_cast<size_t>(d)]);
            py::dict out;
            out["kind"] = to_string(b.kind);
            out["dofs"] = dofs;
            out["harmonic"] = b.harmonic;
            out["cos"] = b.cos_part;
            out["sin"] = b.sin_part;
            return out;
          },
          "[base_motion] as {kind, dofs, harmonic, cos, sin} (results are the motion relative to the base); None when absent")
      .def_property_readonly("outputs",
                             [](const CaseDefinition& c) {
                               std::vector<std::string> names;
                               for (const auto& o : c.outputs) names.push_back(o.name);
                               return names;
                             })
      .def_property_readonly(
          "parameters",
          [](const CaseDefinition& c) {
            py::dict out;
            for (int i = 0; i < c.parameters.size(); ++i)
              out[py::str(c.parameters.names()[static_cast<size_t>(i)])] = c.parameters.value(i);
            return out;
          },
          "named parameters {name: value} (a copy: change them with set_parameter)")
      .def(
          "set_parameter",
          [](CaseDefinition& c, const std::string& name, double value) {
            const int index = c.parameters.find(name);
            if (index < 0) {
              std::string known;
              for (const std::string& n : c.parameters.names()) known += (known.empty() ? "" : ", ") + n;
              throw CaseError("set_parameter: unknown parameter '" + name + "' (the case has: " + known + ")");
            }
            if (const std::string why = c.parameters.fixed_reason(index); !why.empty())
              throw CaseError("set_parameter: '" + name + "' " + why + " (load_case(path, set={...}) rebuilds it)");
            c.parameters.value(index) = value;
          },
          py::arg("name"), py::arg("value"))
      .def("__repr__", [](const CaseDefinition& c) {
        std::string text = "Case(path=";
        text += py::repr(py::str(c.path)).cast<std::string>();
        text += ", dofs=";
        text += std::to_string(c.model.dofs());
        text += ", elements=";
        text += std::to_string(c.elements.size());
        text += ")";
        return text;
      });
  bind_case_settings(m, case_class);
  m.def("load_case", &load_case, py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
        "the case file at path with NAME=VALUE overrides (as hbtrack --set)");
}

}  // namespace hbtrack::python
