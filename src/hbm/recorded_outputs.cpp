#include "hbtrack/hbm/recorded_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hbtrack {

Eigen::VectorXd dof_signal(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, int samples) {
  // cos and sin of j tau_i are those of sample (j i mod samples): one table of the period's
  // samples instead of 2 H trigonometric calls per sample (a third of a small model's run when
  // every point records its outputs' extremes).
  thread_local Eigen::VectorXd cosines, sines;
  if (cosines.size() != samples) {
    cosines.resize(samples);
    sines.resize(samples);
    for (int i = 0; i < samples; ++i) {
      const double tau = 2.0 * std::numbers::pi * i / samples;
      cosines(i) = std::cos(tau);
      sines(i) = std::sin(tau);
    }
  }
  Eigen::VectorXd x(samples);
  for (int i = 0; i < samples; ++i) {
    double v = 0.5 * full(dof);
    long long at = 0;  // j i mod samples
    for (int j = 1; j <= harmonics; ++j) {
      at += i;
      if (at >= samples) at -= samples;
      v += full((2 * j - 1) * dofs + dof) * cosines(at) + full(2 * j * dofs + dof) * sines(at);
    }
    x(i) = v;
  }
  return x;
}

Eigen::VectorXd dof_harmonics(const Eigen::VectorXd& full, int dofs, int harmonics, int dof) {
  Eigen::VectorXd h(2 * harmonics + 1);
  for (int k = 0; k <= 2 * harmonics; ++k) h(k) = full(k * dofs + dof);
  return h;
}

OutputValues output_values(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, int samples) {
  const Eigen::VectorXd x = dof_signal(full, dofs, harmonics, dof, samples);
  OutputValues out;
  out.max = x.maxCoeff();
  out.min = x.minCoeff();
  out.h1 = harmonics >= 1 ? std::hypot(full(dofs + dof), full(2 * dofs + dof)) : 0.0;
  out.harmonics = dof_harmonics(full, dofs, harmonics, dof);
  return out;
}

double harmonic_magnitude(const Eigen::VectorXd& harmonics, int k) {
  return k == 0 ? 0.5 * harmonics(0) : std::hypot(harmonics(2 * k - 1), harmonics(2 * k));
}

double harmonic_phase(const Eigen::VectorXd& harmonics, int k) {
  double largest = std::abs(0.5 * harmonics(0));
  for (int j = 1; 2 * j < harmonics.size(); ++j) largest = std::max(largest, harmonic_magnitude(harmonics, j));
  if (harmonic_magnitude(harmonics, k) <= 1e-12 * largest) return 0.0;
  return std::atan2(harmonics(2 * k), harmonics(2 * k - 1));
}

}  // namespace hbtrack
