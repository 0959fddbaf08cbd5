// Harmonic balance solutions read back: the Fourier coefficients of each output dof at a point,
// and the balance's residual at any state (another tool's points in hbtrack's equations).
#include <pybind11/eigen.h>

#include "bindings.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::python {

namespace {

// The case's harmonic balance, after checking that `state` [omega, unknowns...] belongs to it.
HarmonicBalance harmonic_balance_for(const CaseDefinition& c, const Eigen::VectorXd& state) {
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  if (state.size() != 1 + hbm.unknowns())
    throw CaseError("state: holds " + std::to_string(state.size() - 1) + " unknowns after omega, the case has " +
                    std::to_string(hbm.unknowns()) + " (a result of another case?)");
  return hbm;
}

}  // namespace

void bind_hbm(py::module_& m) {
  m.def(
      "output_harmonics",
      [](const CaseDefinition& c, const Eigen::VectorXd& state) {
        HarmonicBalance hbm = harmonic_balance_for(c, state);
        const Eigen::VectorXd full = hbm.expand(state.tail(hbm.unknowns()), state(0));
        py::dict out;
        for (const OutputDof& o : c.outputs)
          out[py::str(o.name)] = dof_harmonics(full, c.model.dofs(), c.harmonic_balance.harmonics, o.dof);
        return out;
      },
      py::arg("case"), py::arg("state"),
      "{output name: [a0, a1, b1, ..., aH, bH]} (x = a0/2 + sum a_j cos + b_j sin) of a state row [omega, x0, x1, ...]");
  m.def(
      "residual",
      [](const CaseDefinition& c, const Eigen::VectorXd& state) {
        HarmonicBalance hbm = harmonic_balance_for(c, state);
        Eigen::VectorXd r;
        hbm.evaluate(state.tail(hbm.unknowns()), state(0), r);
        // The scale `frc` measures convergence against (its tolerance is on ||r||inf / scale).
        const double scale = force_scale(hbm, automatic_length_scale(hbm, state(0), state(0)));
        py::dict out;
        out["residual"] = r;
        out["force_scale"] = scale;
        out["relative"] = r.size() > 0 ? r.cwiseAbs().maxCoeff() / scale : 0.0;
        return out;
      },
      py::arg("case"), py::arg("state"),
      "{residual, force_scale, relative}: the harmonic balance residual of a state row [omega, x0, x1, ...]");
}

}  // namespace hbtrack::python
