#pragma once
// The harmonics of every dof as states.csv and special_states.csv hold them (docs/outputs.md):
// after the leading columns (omega; track: leg, omega, the parameter), per model dof NAME in the
// model's order and per harmonic balanced K (its multiple of omega, "0.5" on a period-doubled
// branch): NAME_h0 (the mean), NAME_cK, NAME_sK, so that
//   x_NAME(t) = NAME_h0 + sum_K NAME_cK cos(K omega t) + NAME_sK sin(K omega t).
// The linear dofs a condensation removed are recovered; the retained dofs are copied from the
// unknowns, so that a restart reads back exactly the unknowns it was written from.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack {

// The column of coefficient c (basis order) of a signal `name`: NAME_h0, NAME_cK or NAME_sK.
std::string harmonic_column(const HarmonicBalance& hbm, const std::string& name, int c);
// The value stored for coefficient c: the mean a0 / 2 for the a0 coefficient (exact in binary, so
// twice it is a0 again), the coefficient itself otherwise.
double stored_coefficient(const FourierBasis& basis, int c, double coefficient);
// The dof columns (without the leading ones).
std::vector<std::string> dof_state_columns(const HarmonicBalance& hbm);
// Their values at the solution x (unknown layout) at omega.
std::vector<double> dof_state_values(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega);

// The same at a point of a curve in parameter `parameter` (a tracking curve), at its own `value`
// of it (the condensed dofs' recovery depends on it), by an evaluator of its own: hbm's values hold.
std::vector<double> dof_state_values(const HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int parameter, double value);
// states.csv of a branch: omega, then the dof columns.
std::vector<std::string> dof_state_header(const HarmonicBalance& hbm);
std::vector<double> dof_state_row(HarmonicBalance& hbm, double omega, const Eigen::VectorXd& x);
// The same at a point of a branch in parameter `parameter` (hbtrack continue), at its `value`.
std::vector<double> dof_state_row(const HarmonicBalance& hbm, double omega, const Eigen::VectorXd& x, int parameter, double value);

// True for the layout written before the dof columns: x0, x1, ... the unknowns themselves, the
// mean as a0 (x = a0/2 + ...).
bool is_unknown_layout(const std::vector<std::string>& columns);
// The unknowns of hbm from a row's columns after the leading ones, either layout (the unknown
// layout is returned as it is: the caller checks its size). Throws std::invalid_argument naming
// the first column the system needs and the row lacks.
Eigen::VectorXd unknowns_from_state(const HarmonicBalance& hbm, const std::vector<std::string>& columns, const std::vector<double>& values);

}  // namespace hbtrack
