#include "hbtrack/results/element_force_table.hpp"

#include "hbtrack/results/state_columns.hpp"

namespace hbtrack {

namespace {
std::string element_dof(const HarmonicBalance& hbm, size_t element, int local) {
  std::string name = "element";  // appended, not operator+: GCC 12's false -Wrestrict at -O3
  name += std::to_string(element);
  name += "_";
  name += hbm.model().dof_names[static_cast<size_t>(hbm.elements()[element]->dofs[static_cast<size_t>(local)])];
  return name;
}
}  // namespace

std::vector<std::string> element_force_header(const HarmonicBalance& hbm) {
  std::vector<std::string> header{"omega"};
  for (size_t e = 0; e < hbm.elements().size(); ++e)
    for (int i = 0; i < hbm.elements()[e]->local_dofs(); ++i) {
      const std::string name = element_dof(hbm, e, i);
      for (int c = 0; c < hbm.basis().coefficients(); ++c) header.push_back(harmonic_column(hbm, name, c));
      header.push_back(name + "_max");
      header.push_back(name + "_min");
    }
  return header;
}

std::vector<double> element_force_row(HarmonicBalance& hbm, double omega, const Eigen::VectorXd& x) {
  std::vector<double> row{omega};
  const FourierBasis& basis = hbm.basis();
  for (const Eigen::MatrixXd& samples : hbm.element_force_samples(x, omega)) {
    const Eigen::MatrixXd coefficients = basis.analysis() * samples;  // nc x k
    for (Eigen::Index i = 0; i < samples.cols(); ++i) {
      for (int c = 0; c < basis.coefficients(); ++c) row.push_back(stored_coefficient(basis, c, coefficients(c, i)));
      row.push_back(samples.col(i).maxCoeff());
      row.push_back(samples.col(i).minCoeff());
    }
  }
  return row;
}

}  // namespace hbtrack
