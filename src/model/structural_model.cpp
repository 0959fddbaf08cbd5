#include "hbtrack/model/structural_model.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace hbtrack {

double ForcingGrowth::factor(double omega) const { return active() ? std::pow(omega / reference_frequency, exponent) : 1.0; }

double ForcingGrowth::derivative(double omega) const {
  return active() ? exponent / reference_frequency * std::pow(omega / reference_frequency, exponent - 1.0) : 0.0;
}

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
  if (!(forcing_growth.exponent >= 0.0) || !std::isfinite(forcing_growth.exponent))
    throw std::invalid_argument("forcing_growth.exponent: must be >= 0 and finite (the forcing grows as (omega/omega_ref)^k), got " +
                                std::to_string(forcing_growth.exponent));
  if (!(forcing_growth.reference_frequency > 0.0) || !std::isfinite(forcing_growth.reference_frequency))
    throw std::invalid_argument("forcing_growth.reference_frequency: must be > 0 and finite [rad/s], got " +
                                std::to_string(forcing_growth.reference_frequency));
}

}  // namespace hbtrack
