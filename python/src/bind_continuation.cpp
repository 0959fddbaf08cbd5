// Continuation in a named parameter at fixed omega and nonlinear modes (backbones): the runs of
// hbtrack continue / backbone (src/runs/), into tables in memory.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/backbone.hpp"
#include "hbtrack/runs/parameter_branch.hpp"
#include "python_monitor.hpp"

namespace hbtrack::python {

namespace {

// progress(fraction of [start, end] covered, point, the parameter's value).
py::dict continuation(const CaseDefinition& c, const std::string& param, double omega, double start, double end,
                      const py::object& progress) {
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) {
    runs::continue_in_parameter(c, {param, omega, start, end}, sink, monitor);
  });
}

// `hbtrack backbone`, mode from 1; progress(fraction of [log start, log end] covered, point, the
// modal amplitude).
py::dict backbone(const CaseDefinition& c, int mode, double start, double end, const py::object& progress) {
  BackboneOptions options;
  options.mode = mode;
  options.amplitude_start = start;
  options.amplitude_end = end;
  return run_in_memory(progress, [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::backbone(c, options, sink, monitor); });
}

}  // namespace

void bind_continuation(py::module_& m) {
  m.def("continuation", &continuation, py::arg("case"), py::arg("param"), py::arg("omega"), py::arg("start"), py::arg("end"),
        py::arg("progress") = py::none(),
        "continuation in a named parameter at fixed omega: {branch, states, dof_states, special_points, special_states, "
        "dof_special_states, summary}");
  m.def("backbone", &backbone, py::arg("case"), py::arg("mode"), py::arg("start"), py::arg("end"), py::arg("progress") = py::none(),
        "nonlinear mode (EPMC) from the linear mode: {branch, states, dof_states, special_points, summary}");
}

}  // namespace hbtrack::python
