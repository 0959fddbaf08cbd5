#pragma once
// A parametric fan blade standing in for the (non-public) NASA rotor 67 mesh of the paper: a
// twisted, tapered, optionally cambered plate of 20-node hexahedra, clamped at the root.
//   X is the rotation (axial) axis; the blade stacks along +Y from the hub radius to the tip
//   radius; each cross-section is a rectangle (chord x thickness) centred on the stacking line,
//   turned by the stagger angle from the axial direction towards the circumferential one (+Z).
// Chord, thickness and stagger vary linearly from root to tip. The default geometry is tuned so
// that the first three modes are 1B, 2B and 1T within 5 % of the paper's 2039.78, 6343.69 and
// 10745.26 rad/s (scripts/make-blade-rom.sh prints them and the mesh convergence).
#include <vector>

#include "hbtrack/model/blade_mesh.hpp"

namespace hbtrack {

struct BladeGeometry {
  // Fitted (Nelder-Mead on the full FE model, then rounded) to the paper's 1B, 2B, 1T; the radii
  // are rotor 67's order of magnitude. The twist couples flap and torsion: without it 2B/1B of a
  // plate this tapered stays near 4 and 1T falls below 2B. The camber makes the blade, like a
  // real one, asymmetric between leading and trailing edge: a flat plate twisted about its
  // mid-chord is symmetric under a half turn about the span, and so is its tip contact.
  double hub_radius = 0.080;                               // m, root section (clamped)
  double tip_radius = 0.260;                               // m, tip section (where the 9 contact nodes are)
  double root_chord = 0.078, tip_chord = 0.042;            // m
  double root_thickness = 0.0091, tip_thickness = 0.0025;  // m
  double root_stagger_deg = 16.0, tip_stagger_deg = 64.0;  // chord angle from the axial direction
  double camber = 0.03;                                    // mid-chord camber height / chord (a parabolic arc; 0 is a flat plate)
  IsotropicMaterial material{108e9, 0.34, 4400.0};         // TA6V, as in the paper

  // Elements along chord, thickness and span at refinement 1. The chord count of 4 gives the
  // 2 * 4 + 1 = 9 tip nodes of the paper; the thickness count is even so that mid-thickness
  // nodes exist at every chord station.
  int chord_elements = 4, thickness_elements = 2, span_elements = 12;

  double span() const { return tip_radius - hub_radius; }
  void validate() const;  // throws std::invalid_argument
};

struct BladeModel : BladeMesh {
  BladeGeometry geometry;
  int refinement = 1;

  // Unit vectors of the section at span fraction s in [0, 1]: along the chord (leading to
  // trailing edge) and out of plane (the thickness direction).
  Eigen::Vector3d chord_direction(double s) const;
  Eigen::Vector3d out_of_plane_direction(double s) const;
  double span_fraction(int node) const;
};

// Builds the mesh with every element count multiplied by `refinement` (>= 1); the 9 tip nodes
// stay at the same chord stations. Throws std::invalid_argument for a bad geometry.
BladeModel generate_blade(const BladeGeometry& geometry, int refinement = 1);

}  // namespace hbtrack
