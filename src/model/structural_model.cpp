#include "hbtrack/model/structural_model.hpp"

#include <Eigen/Cholesky>
#include <set>
#include <stdexcept>
#include <string>

namespace hbtrack {

int StructuralModel::find_dof(const std::string& name) const {
  for (size_t i = 0; i < dof_names.size(); ++i)
    if (dof_names[i] == name) return static_cast<int>(i);
  return -1;
}

namespace {
void check_square(const Eigen::MatrixXd& m, int n, const char* what) {
  if (m.rows() != n || m.cols() != n)
    throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(n) + "x" + std::to_string(n) +
                                " (one row per dof), got " + std::to_string(m.rows()) + "x" + std::to_string(m.cols()));
  if (!m.allFinite()) throw std::invalid_argument(std::string(what) + ": contains NaN or Inf");
}
bool symmetric(const Eigen::MatrixXd& m) {
  const double scale = std::max(m.cwiseAbs().maxCoeff(), 1e-300);
  return (m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-10 * scale;
}
}  // namespace

void StructuralModel::validate() const {
  const int n = dofs();
  if (n == 0) throw std::invalid_argument("model.dofs: the model has no dof");
  std::set<std::string> seen;
  for (const auto& name : dof_names)
    if (!seen.insert(name).second) throw std::invalid_argument("model.dofs: dof name '" + name + "' appears twice");
  check_square(mass, n, "model.M");
  check_square(stiffness, n, "model.K");
  check_square(damping, n, "damping.C");
  if (!symmetric(mass)) throw std::invalid_argument("model.M: must be symmetric");
  if (!symmetric(stiffness)) throw std::invalid_argument("model.K: must be symmetric");
  if (Eigen::LLT<Eigen::MatrixXd>(mass).info() != Eigen::Success) throw std::invalid_argument("model.M: must be positive definite");
  for (const HarmonicForce& f : forcing) {
    if (f.order < 0) throw std::invalid_argument("forcing.harmonic: must be >= 0, got " + std::to_string(f.order));
    if (f.cos_part.size() != n || f.sin_part.size() != n)
      throw std::invalid_argument("forcing: force vectors must have one entry per dof (" + std::to_string(n) + ")");
  }
}

}  // namespace hbtrack
