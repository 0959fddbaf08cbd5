#include "hbtrack/results/state_columns.hpp"

#include <stdexcept>
#include <unordered_map>

namespace hbtrack {

std::string harmonic_column(const HarmonicBalance& hbm, const std::string& name, int c) {
  const FourierBasis& basis = hbm.basis();
  const int k = basis.harmonic_of(c);
  std::string column = name;  // appended, not operator+: GCC 12's false -Wrestrict at -O3
  if (k == 0) {
    column += "_h0";
    return column;
  }
  column += basis.is_sine(c) ? "_s" : "_c";
  column += harmonic_label(k, hbm.subharmonic());
  return column;
}

double stored_coefficient(const FourierBasis& basis, int c, double coefficient) {
  return basis.harmonic_of(c) == 0 ? 0.5 * coefficient : coefficient;
}

std::vector<std::string> dof_state_columns(const HarmonicBalance& hbm) {
  std::vector<std::string> columns;
  for (const std::string& name : hbm.model().dof_names)
    for (int c = 0; c < hbm.basis().coefficients(); ++c) columns.push_back(harmonic_column(hbm, name, c));
  return columns;
}

std::vector<double> dof_state_values(HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega) {
  const FourierBasis& basis = hbm.basis();
  const int n = hbm.model().dofs(), q = hbm.retained_dofs(), nc = basis.coefficients();
  // Every dof's coefficients, basis order, harmonic-major (the condensed dofs recovered).
  Eigen::VectorXd full(static_cast<Eigen::Index>(n) * nc);
  if (q < n) full = basis.from_dense(hbm.expand(x, omega), n);
  for (int r = 0; r < q; ++r)  // the unknowns themselves (a modal recovery would round them)
    for (int c = 0; c < nc; ++c) full(c * n + hbm.retained()[static_cast<size_t>(r)]) = x(c * q + r);
  std::vector<double> values;
  values.reserve(static_cast<size_t>(n * nc));
  for (int dof = 0; dof < n; ++dof)
    for (int c = 0; c < nc; ++c) values.push_back(stored_coefficient(basis, c, full(c * n + dof)));
  return values;
}

std::vector<double> dof_state_values(const HarmonicBalance& hbm, const Eigen::VectorXd& x, double omega, int parameter, double value) {
  HarmonicBalance at = hbm.with_parameter(parameter, value);
  return dof_state_values(at, x, omega);
}

std::vector<std::string> dof_state_header(const HarmonicBalance& hbm) {
  std::vector<std::string> header{"omega"};
  const std::vector<std::string> columns = dof_state_columns(hbm);
  header.insert(header.end(), columns.begin(), columns.end());
  return header;
}

namespace {
std::vector<double> row_at(double omega, const std::vector<double>& values) {
  std::vector<double> row{omega};
  row.insert(row.end(), values.begin(), values.end());
  return row;
}
}  // namespace

std::vector<double> dof_state_row(HarmonicBalance& hbm, double omega, const Eigen::VectorXd& x) {
  return row_at(omega, dof_state_values(hbm, x, omega));
}

std::vector<double> dof_state_row(const HarmonicBalance& hbm, double omega, const Eigen::VectorXd& x, int parameter, double value) {
  return row_at(omega, dof_state_values(hbm, x, omega, parameter, value));
}

bool is_unknown_layout(const std::vector<std::string>& columns) { return !columns.empty() && columns.front() == "x0"; }

Eigen::VectorXd unknowns_from_state(const HarmonicBalance& hbm, const std::vector<std::string>& columns,
                                    const std::vector<double>& values) {
  if (is_unknown_layout(columns)) return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  std::unordered_map<std::string, size_t> position;
  for (size_t i = 0; i < columns.size(); ++i) position.emplace(columns[i], i);
  const FourierBasis& basis = hbm.basis();
  const int q = hbm.retained_dofs(), nc = basis.coefficients();
  Eigen::VectorXd x(hbm.unknowns());
  for (int r = 0; r < q; ++r) {
    const std::string& name = hbm.model().dof_names[static_cast<size_t>(hbm.retained()[static_cast<size_t>(r)])];
    for (int c = 0; c < nc; ++c) {
      const std::string column = harmonic_column(hbm, name, c);
      const auto found = position.find(column);
      if (found == position.end() || found->second >= values.size())
        throw std::invalid_argument("no column " + column + " (the case's dof " + name + " at harmonic " +
                                    harmonic_label(basis.harmonic_of(c), hbm.subharmonic()) +
                                    "): results of another case or harmonic balance?");
      const double stored = values[found->second];
      x(c * q + r) = basis.harmonic_of(c) == 0 ? 2.0 * stored : stored;
    }
  }
  return x;
}

}  // namespace hbtrack
