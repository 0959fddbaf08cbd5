#include "hbtrack/model/blade_mesh.hpp"

#include <stdexcept>

namespace hbtrack {

AssembledMatrices assemble_blade(const BladeMesh& blade) { return assemble_hex20(blade.grid.mesh(), blade.material, blade.dofs); }

std::vector<bool> root_face_clamped(const StructuredHex20Grid& grid) {
  std::vector<bool> clamped(static_cast<size_t>(grid.mesh().node_count()), false);
  for (int j = 0; j <= 2 * grid.cells(1); ++j)
    for (int i = 0; i <= 2 * grid.cells(0); ++i) {
      const int node = grid.node_at(i, j, 0);
      if (node >= 0) clamped[static_cast<size_t>(node)] = true;
    }
  return clamped;
}

void find_blade_lines(BladeMesh& blade, int first_airfoil_span_index) {
  const auto& grid = blade.grid;
  const auto& nodes = grid.mesh().nodes;
  if (grid.cells(0) % 4 != 0) throw std::invalid_argument("blade mesh: the chord element count must be a multiple of 4 (9 tip nodes)");
  if (grid.cells(1) % 2 != 0) throw std::invalid_argument("blade mesh: the thickness element count must be even (mid-thickness nodes)");
  const int mid_thickness = grid.cells(1), thickness_end = 2 * grid.cells(1);
  const int tip = 2 * grid.cells(2), chord_end = 2 * grid.cells(0), tip_stride = chord_end / 8;
  auto position = [&](int i, int j, int k) -> const Eigen::Vector3d& { return nodes[static_cast<size_t>(grid.node_at(i, j, k))]; };
  blade.tip_nodes.clear();
  blade.tip_frames.clear();
  for (int station = 0; station <= 8; ++station) {
    const int node = grid.node_at(station * tip_stride, mid_thickness, tip);
    blade.tip_nodes.push_back(node);
    blade.tip_frames.push_back(cylindrical_frame_about_x(nodes[static_cast<size_t>(node)]));
  }
  blade.leading_edge_line.clear();
  blade.mid_chord_line.clear();
  blade.trailing_edge_line.clear();
  blade.station_chord.clear();
  blade.station_normal.clear();
  // Span stations at element corners (even k), where leading edge, mid-chord and trailing edge
  // all have a mid-thickness node.
  for (int k = first_airfoil_span_index; k <= tip; k += 2) {
    blade.leading_edge_line.push_back(grid.node_at(0, mid_thickness, k));
    blade.mid_chord_line.push_back(grid.node_at(chord_end / 2, mid_thickness, k));
    blade.trailing_edge_line.push_back(grid.node_at(chord_end, mid_thickness, k));
    const Eigen::Vector3d chord = (position(chord_end, mid_thickness, k) - position(0, mid_thickness, k)).normalized();
    Eigen::Vector3d across = position(chord_end / 2, 0, k) - position(chord_end / 2, thickness_end, k);
    across -= across.dot(chord) * chord;  // the section's plane is spanned by chord and normal
    blade.station_chord.push_back(chord);
    blade.station_normal.push_back(across.normalized());
  }
}

int blade_rotation_sense(const BladeMesh& blade) {
  const auto& nodes = blade.grid.mesh().nodes;
  const Eigen::Vector3d lead = nodes[static_cast<size_t>(blade.tip_nodes.front())] - nodes[static_cast<size_t>(blade.tip_nodes.back())];
  const double ahead = lead.dot(blade.tip_frames[blade.tip_frames.size() / 2].circumferential());
  if (ahead == 0.0) throw std::invalid_argument("blade mesh: the tip chord is axial, no sense of rotation makes its leading edge lead");
  return ahead > 0 ? 1 : -1;
}

}  // namespace hbtrack
