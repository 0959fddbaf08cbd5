#pragma once
// Node coordinates from a CalculiX (or Abaqus-style) input deck, JOB.inp: the data lines of every
// `*NODE` block (`id, x[, y[, z]]`, a missing coordinate is 0, as ccx reads it), following
// `*INCLUDE, INPUT=file` (relative to the including file). `**` lines are comments; keywords are
// case-insensitive. Decks whose matrices would not be in the global x, y, z directions are
// refused: `*NODE, SYSTEM=` other than R, and `*TRANSFORM`. Every failure throws
// std::runtime_error with one line "<path>: line N: <rule>".
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace hbtrack {

struct CalculixNode {
  int id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// In the order the deck defines them; a node defined twice is an error.
std::vector<CalculixNode> read_calculix_input_nodes(const std::string& inp_path);

}  // namespace hbtrack
