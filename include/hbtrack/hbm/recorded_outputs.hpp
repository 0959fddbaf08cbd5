#pragma once
// What a branch records per point for each named output dof: the extremes of its displacement
// over one period and the magnitude of its first harmonic (the result-folder contract in README "Using it").
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace hbtrack {

struct OutputDof {
  std::string name;
  int dof = -1;             // model dof index
  std::string description;  // what figures call it ("leading-edge tip node"); "" for none
};

struct OutputValues {
  double max = 0, min = 0, h1 = 0;
  // [a0, a1, b1, ..., aH, bH] (the layout of dof_harmonics): branch.csv's hK_ and phaseK_ columns.
  Eigen::VectorXd harmonics;
};

// Magnitude of harmonic k of [a0, a1, b1, ...]: k = 0 the mean a0/2 (signed), k >= 1 |(a_k, b_k)|.
double harmonic_magnitude(const Eigen::VectorXd& harmonics, int k);
// Phase of harmonic k >= 1 in radians, in (-pi, pi]: a_k cos + b_k sin = |c| cos(k w t - phase);
// 0 for a harmonic below 1e-12 of the largest one (round-off, e.g. Duffing's even harmonics,
// whose atan2 would be noise).
double harmonic_phase(const Eigen::VectorXd& harmonics, int k);

// `full` holds n(2H+1) harmonic-major coefficients of every dof; the period is sampled at
// `samples` instants to find the extremes.
OutputValues output_values(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, int samples);

// Fourier coefficients of one dof, [a0, a1, b1, ..., aH, bH] with x = a0/2 + sum a_j cos + b_j sin
// (the layout of a simulation's PeriodSummary::harmonics, so the two compare entry by entry).
Eigen::VectorXd dof_harmonics(const Eigen::VectorXd& full, int dofs, int harmonics, int dof);

// Time signal of one dof over a period at `samples` equally spaced instants.
Eigen::VectorXd dof_signal(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, int samples);

}  // namespace hbtrack
