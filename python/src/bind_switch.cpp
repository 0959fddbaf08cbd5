// Branch switching at a BP or PD of an NFRC: the run of `hbtrack switch` (src/runs/), into
// tables in memory.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/switch_branch.hpp"
#include "python_monitor.hpp"

namespace hbtrack::python {

namespace {

// type: "BP" or "PD" (the caster parses the name); (omega, x) the point; before/after its neighbours on the NFRC.
// progress(fraction, point, omega): each of the two legs counts for half.
py::dict switch_branch(const CaseDefinition& period_one, SpecialPointType type, int point, double omega, const Eigen::VectorXd& x,
                       double omega_before, const Eigen::VectorXd& x_before, double omega_after, const Eigen::VectorXd& x_after,
                       const py::object& progress) {
  const runs::SwitchOptions options{type, point, {omega, x, "start"}, {omega_before, x_before, "start"}, {omega_after, x_after, "start"}};
  return run_in_memory(progress,
                       [&](runs::ResultSink& sink, runs::RunMonitor& monitor) { runs::switch_branch(period_one, options, sink, monitor); });
}

}  // namespace

void bind_switch(py::module_& m) {
  m.def("switch", &switch_branch, py::arg("case"), py::arg("type"), py::arg("point"), py::arg("omega"), py::arg("x"),
        py::arg("omega_before"), py::arg("x_before"), py::arg("omega_after"), py::arg("x_after"), py::arg("progress") = py::none(),
        "the branch through a BP, or the period-doubled branch of a PD: {branch, states, dof_states, special_points, special_states, "
        "dof_special_states, summary}");
}

}  // namespace hbtrack::python
