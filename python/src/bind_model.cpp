// Model building blocks: Craig-Bampton reduction (hbtrack reduce) and normal modes.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "gil_release.hpp"
#include "hbtrack/model/craig_bampton.hpp"
#include "hbtrack/model/damping.hpp"

namespace hbtrack::python {

namespace {

// boundary: per node its three full-model rows (x, y, z); frames: per node the 3x3 matrix whose
// columns are its local r, t, z axes (identity when omitted). M and K arrive as scipy.sparse
// (compressed columns) so that a finite-element model is never densified.
py::dict reduce_sparse(const Eigen::SparseMatrix<double>& mass, const Eigen::SparseMatrix<double>& stiffness,
                       const std::vector<std::array<int, 3>>& boundary, const std::vector<Eigen::MatrixXd>& frames, int modes) {
  if (!frames.empty() && frames.size() != boundary.size())
    throw std::invalid_argument("frames: one per boundary node (" + std::to_string(boundary.size()) + "), got " +
                                std::to_string(frames.size()));
  std::vector<CraigBamptonBoundaryNode> nodes(boundary.size());
  for (size_t k = 0; k < boundary.size(); ++k) {
    nodes[k].dofs = boundary[k];
    if (frames.empty()) continue;
    if (frames[k].rows() != 3 || frames[k].cols() != 3) throw std::invalid_argument("frames[" + std::to_string(k) + "]: expected 3x3");
    nodes[k].frame = frames[k];
  }
  CraigBamptonModel r;
  {
    GilRelease release;
    r = craig_bampton(mass, stiffness, nodes, modes);
  }
  py::dict out;
  out["mass"] = r.mass;
  out["stiffness"] = r.stiffness;
  out["transformation"] = r.transformation;
  out["fixed_interface_frequencies"] = r.fixed_interface_frequencies;
  out["dof_names"] = r.dof_names;
  return out;
}

// The same from dense numpy arrays (pybind11's sparse caster imports scipy: numpy-only users
// come through here).
py::dict reduce(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness, const std::vector<std::array<int, 3>>& boundary,
                const std::vector<Eigen::MatrixXd>& frames, int modes) {
  return reduce_sparse(mass.sparseView(), stiffness.sparseView(), boundary, frames, modes);
}

}  // namespace

void bind_model(py::module_& m) {
  // Frames arrive as dynamic-size matrices: pybind11's fixed-size 3x3 caster trips GCC 12's
  // -Wmaybe-uninitialized.
  m.def("reduce", &reduce, py::arg("mass"), py::arg("stiffness"), py::arg("boundary"), py::arg("frames") = std::vector<Eigen::MatrixXd>{},
        py::arg("modes") = 12, "Craig-Bampton reduction onto boundary node translations and fixed-interface modes");
  m.def("reduce_sparse", &reduce_sparse, py::arg("mass"), py::arg("stiffness"), py::arg("boundary"),
        py::arg("frames") = std::vector<Eigen::MatrixXd>{}, py::arg("modes") = 12, "reduce, from scipy.sparse M and K");
  m.def(
      "normal_modes",
      [](const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness) {
        const NormalModes modes = normal_modes(mass, stiffness);
        return py::make_tuple(modes.frequencies, modes.shapes);
      },
      py::arg("mass"), py::arg("stiffness"), "undamped modes: (frequencies in rad/s, mass-normalised shapes as columns)");
}

}  // namespace hbtrack::python
