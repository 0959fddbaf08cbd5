#include "python_monitor.hpp"

#include <string>

namespace hbtrack::python {

namespace {

// The Python key of a run's table, and whether it is handed back as a 2-D array.
std::pair<std::string, bool> python_key(const std::string& table) {
  if (table == "states") return {"dof_states", false};
  if (table == "special_states") return {"dof_special_states", false};
  if (table == "unknowns") return {"states", true};
  if (table == "special_unknowns") return {"special_states", true};
  return {table, false};
}

}  // namespace

py::dict result_dict(const runs::MemorySink& sink) {
  py::dict out;
  for (const auto& [name, memory] : sink.tables()) {
    const Table table{memory.header, memory.rows};
    const auto [key, as_matrix] = python_key(name);
    if (as_matrix)
      out[py::str(key)] = table.matrix();
    else
      out[py::str(key)] = table.columns();
  }
  if (!sink.children().empty()) {
    py::dict branches;
    for (const auto& [name, child] : sink.children()) branches[py::str(name)] = result_dict(*child);
    out["branches"] = branches;
  }
  const py::object summary = to_python(sink.last_summary());
  out["summary"] = summary;
  if (sink.last_summary().contains("special_points")) out["special_points"] = summary["special_points"];
  return out;
}

}  // namespace hbtrack::python
