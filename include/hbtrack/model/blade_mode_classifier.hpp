#pragma once
// Names a mode of a generated blade from its shape: family from the tip (the 9 mid-thickness
// tip nodes), order from the span.
//   bending (B):   tip motion dominated by the out-of-plane (thickness) direction, same sign at
//                  every chord station;
//   torsion (T):   out-of-plane dominated, changing sign across the chord;
//   edgewise (E):  tip motion dominated by the in-plane chord direction;
// order: 1 + the sign changes along the span of the out-of-plane displacement at mid-chord
// (bending), of the twist (torsion) or of the chordwise displacement (edgewise).
#include <string>

#include "hbtrack/model/blade_mesh.hpp"

namespace hbtrack {

struct BladeModeType {
  char family = '?';  // 'B', 'T', 'E', or '?' when the tip barely moves (e.g. a radial mode)
  int order = 0;
  std::string label() const;  // "1B", "2B", "1T", ..., or "?"
};

// `shape` is over the blade's free dofs (as assembled), any normalisation.
BladeModeType classify_blade_mode(const BladeMesh& blade, const Eigen::VectorXd& shape);

}  // namespace hbtrack
