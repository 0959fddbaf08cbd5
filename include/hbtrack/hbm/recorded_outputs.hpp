#pragma once
// What a branch records per point for each named output dof: the extremes of its displacement
// over one period and the magnitude of its first harmonic (the result-folder contract in README "Using it").
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace hbtrack {

struct OutputDof {
  std::string name;
  int dof = -1;  // model dof index
};

struct OutputValues {
  double max = 0, min = 0, h1 = 0;
};

// `full` holds n(2H+1) harmonic-major coefficients of every dof; the period is sampled at
// `samples` instants to find the extremes.
OutputValues output_values(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, int samples);

// Fourier coefficients of one dof, [a0, a1, b1, ..., aH, bH] with x = a0/2 + sum a_j cos + b_j sin
// (the layout of a simulation's PeriodSummary::harmonics, so the two compare entry by entry).
Eigen::VectorXd dof_harmonics(const Eigen::VectorXd& full, int dofs, int harmonics, int dof);

// Time signal of one dof over a period at `samples` equally spaced instants.
Eigen::VectorXd dof_signal(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, int samples);

}  // namespace hbtrack
