#include "hbtrack/analysis/torus_linear_part.hpp"

#include <complex>
#include <stdexcept>
#include <string>

namespace hbtrack {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXcd;
using Complex = std::complex<double>;

namespace {
MatrixXd rows_and_columns(const MatrixXd& a, const std::vector<int>& rows, const std::vector<int>& columns) {
  MatrixXd out(rows.size(), columns.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < columns.size(); ++j) out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = a(rows[i], columns[j]);
  return out;
}
}  // namespace

TorusLinearPart::TorusLinearPart(const StructuralModel& model, std::vector<int> retained) : retained_(std::move(retained)) {
  std::vector<char> kept(static_cast<size_t>(model.dofs()), 0);
  for (const int d : retained_) {
    if (d < 0 || d >= model.dofs() || kept[static_cast<size_t>(d)])
      throw std::invalid_argument("torus: retained dof " + std::to_string(d) + " is out of range or repeated");
    kept[static_cast<size_t>(d)] = 1;
  }
  for (int d = 0; d < model.dofs(); ++d)
    if (!kept[static_cast<size_t>(d)]) condensed_.push_back(d);
  const auto split = [&](const MatrixXd& a) {
    return Blocks{rows_and_columns(a, retained_, retained_), rows_and_columns(a, retained_, condensed_),
                  rows_and_columns(a, condensed_, retained_), rows_and_columns(a, condensed_, condensed_)};
  };
  mass_ = split(model.mass);
  damping_ = split(model.damping);
  stiffness_ = split(model.stiffness);
}

VectorXcd TorusLinearPart::part(const VectorXcd& full, const std::vector<int>& dofs) const {
  VectorXcd out(dofs.size());
  for (size_t i = 0; i < dofs.size(); ++i) out(static_cast<Eigen::Index>(i)) = full(dofs[i]);
  return out;
}

PairBalance TorusLinearPart::balance(double w, const VectorXcd& z, const VectorXcd* unit_force, double level, bool with_derivatives) const {
  const Complex i(0, 1);
  // Z(w) and dZ/dw of one block.
  const auto z_of = [&](const MatrixXd& k, const MatrixXd& m, const MatrixXd& c) -> MatrixXcd {
    return (k - w * w * m).cast<Complex>() + i * w * c.cast<Complex>();
  };
  const auto dz_of = [&](const MatrixXd& m, const MatrixXd& c) -> MatrixXcd {
    return (-2.0 * w * m).cast<Complex>() + i * c.cast<Complex>();
  };
  const MatrixXcd z_rr = z_of(stiffness_.rr, mass_.rr, damping_.rr);
  PairBalance b;
  VectorXcd force_r, force_l;
  if (unit_force) force_r = part(*unit_force, retained_), force_l = part(*unit_force, condensed_);
  if (!condenses()) {
    b.residual = z_rr * z;
    if (unit_force) b.residual -= level * force_r, b.reduced_force = force_r;
    if (with_derivatives) b.stiffness = z_rr, b.frequency_derivative = dz_of(mass_.rr, damping_.rr) * z;
    return b;
  }
  const MatrixXcd z_rl = z_of(stiffness_.rl, mass_.rl, damping_.rl), z_lr = z_of(stiffness_.lr, mass_.lr, damping_.lr);
  const Eigen::PartialPivLU<MatrixXcd> z_ll(z_of(stiffness_.ll, mass_.ll, damping_.ll));
  // The condensed dofs' response: z_l = Z_ll^-1 (level F_l - Z_lr z).
  VectorXcd rhs = -(z_lr * z);
  if (unit_force) rhs += level * force_l;
  const VectorXcd z_l = z_ll.solve(rhs);
  b.residual = z_rr * z + z_rl * z_l;
  if (unit_force) {
    b.residual -= level * force_r;
    b.reduced_force = force_r - z_rl * z_ll.solve(force_l);
  }
  if (!with_derivatives) return b;
  b.stiffness = z_rr - z_rl * z_ll.solve(z_lr);
  const MatrixXcd dz_rr = dz_of(mass_.rr, damping_.rr), dz_rl = dz_of(mass_.rl, damping_.rl);
  const MatrixXcd dz_lr = dz_of(mass_.lr, damping_.lr), dz_ll = dz_of(mass_.ll, damping_.ll);
  const VectorXcd e_r = dz_rr * z + dz_rl * z_l, e_l = dz_lr * z + dz_ll * z_l;
  b.frequency_derivative = e_r - z_rl * z_ll.solve(e_l);
  return b;
}

}  // namespace hbtrack
