#pragma once
// Meshes of 20-node hexahedra, and the structured generator: an nx x ny x nz grid of elements
// over the unit cube, placed in space by a map (the blade generator bends and twists it).
#include <array>
#include <functional>
#include <vector>

#include "hbtrack/model/hex20_element.hpp"

namespace hbtrack {

struct SolidMesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, kHex20Nodes>> elements;  // node indices, hex20_natural_nodes() order

  int node_count() const { return static_cast<int>(nodes.size()); }
  Hex20Coordinates element_coordinates(int element) const;
};

// Nodes sit on the doubled grid (i, j, k), 0 <= i <= 2 nx, ...: even indices are element
// corners, odd ones mid-edges. Serendipity elements have no face or body centre nodes, so a grid
// position with more than one odd index holds no node.
class StructuredHex20Grid {
 public:
  using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d& unit_cube_point)>;
  // Throws std::invalid_argument for a count < 1.
  StructuredHex20Grid(std::array<int, 3> cells, const Map& map);

  const SolidMesh& mesh() const { return mesh_; }
  int cells(int axis) const { return cells_[static_cast<size_t>(axis)]; }
  // Node at doubled-grid position (i, j, k), or -1 when that position holds none.
  int node_at(int i, int j, int k) const;

 private:
  std::array<int, 3> cells_;
  std::vector<int> node_index_;  // per doubled-grid position
  SolidMesh mesh_;
};

}  // namespace hbtrack
