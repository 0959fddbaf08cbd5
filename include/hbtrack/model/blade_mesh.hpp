#pragma once
// What every generated blade mesh provides, whatever its geometry (the parametric plate of
// blade_generator.hpp or a blade meshed from stream-surface sections, section_blade.hpp): the
// hex20 grid with its clamped dofs, the 9 tip nodes the contact acts on, and the lines and
// directions the mode classifier reads. X is the rotation axis; lengths in metres.
#include <vector>

#include "hbtrack/model/cylindrical_frame.hpp"
#include "hbtrack/model/fe_assembly.hpp"

namespace hbtrack {

struct BladeMesh {
  IsotropicMaterial material;
  StructuredHex20Grid grid;  // axes: chord (leading edge at 0), thickness, span (root at 0)
  DofNumbering dofs;         // root-face nodes clamped
  // The 9 boundary nodes: tip, mid-thickness, leading edge (node 1) to trailing edge (node 9).
  std::vector<int> tip_nodes;
  std::vector<CylindricalFrame> tip_frames;
  // Mid-thickness nodes from root to tip along the leading edge, mid-chord and trailing edge
  // (span stations shared by the three lines), and per station the section's unit vectors along
  // the chord (leading to trailing edge) and out of its plane: the mode classifier reads them.
  std::vector<int> leading_edge_line, mid_chord_line, trailing_edge_line;
  std::vector<Eigen::Vector3d> station_chord, station_normal;
};

AssembledMatrices assemble_blade(const BladeMesh& blade);

// The nodes of the grid's first span face (the blade's root, or its rim's bottom) marked clamped.
std::vector<bool> root_face_clamped(const StructuredHex20Grid& grid);

// Mid-thickness nodes at the even span positions of the grid's lines and the 9 tip nodes (every
// (chord cells / 8)-th doubled position at the tip), and the stations' directions measured on
// the mesh: fills those fields of `blade` from its grid. The lines start at the doubled-grid span
// index `first_airfoil_span_index` (the airfoil's root: 0 without a root block) and end at the
// tip. Throws std::invalid_argument when the chord cell count is not a multiple of 8 / 2 = 4.
void find_blade_lines(BladeMesh& blade, int first_airfoil_span_index);

// The sense of rotation in which the leading edge leads: +1 when the tip's leading-edge node is
// ahead of its trailing-edge node along the circumferential direction of the mid-chord tip
// frame, -1 when behind. The tip_contact elements of a case built on this blade take
// engine_order (or rotation_speed) of this sign, so that friction opposes the blade's motion.
int blade_rotation_sense(const BladeMesh& blade);

}  // namespace hbtrack
