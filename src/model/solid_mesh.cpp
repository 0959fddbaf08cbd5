#include "hbtrack/model/solid_mesh.hpp"

#include <stdexcept>

namespace hbtrack {

Hex20Coordinates SolidMesh::element_coordinates(int element) const {
  Hex20Coordinates xyz;
  const auto& connectivity = elements[static_cast<size_t>(element)];
  for (int a = 0; a < kHex20Nodes; ++a) xyz.row(a) = nodes[static_cast<size_t>(connectivity[static_cast<size_t>(a)])].transpose();
  return xyz;
}

StructuredHex20Grid::StructuredHex20Grid(std::array<int, 3> cells, const Map& map) : cells_(cells) {
  for (int c : cells)
    if (c < 1) throw std::invalid_argument("structured mesh: every direction needs at least one element");
  const int ni = 2 * cells[0] + 1, nj = 2 * cells[1] + 1, nk = 2 * cells[2] + 1;
  node_index_.assign(static_cast<size_t>(ni) * static_cast<size_t>(nj) * static_cast<size_t>(nk), -1);
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        if ((i % 2) + (j % 2) + (k % 2) > 1) continue;
        node_index_[static_cast<size_t>((k * nj + j) * ni + i)] = mesh_.node_count();
        const Eigen::Vector3d unit(double(i) / (ni - 1), double(j) / (nj - 1), double(k) / (nk - 1));
        mesh_.nodes.push_back(map(unit));
      }
  const auto& natural = hex20_natural_nodes();
  for (int ek = 0; ek < cells[2]; ++ek)
    for (int ej = 0; ej < cells[1]; ++ej)
      for (int ei = 0; ei < cells[0]; ++ei) {
        std::array<int, kHex20Nodes> element{};
        for (size_t a = 0; a < element.size(); ++a)
          element[a] = node_at(2 * ei + 1 + natural[a][0], 2 * ej + 1 + natural[a][1], 2 * ek + 1 + natural[a][2]);
        mesh_.elements.push_back(element);
      }
}

int StructuredHex20Grid::node_at(int i, int j, int k) const {
  const int ni = 2 * cells_[0] + 1, nj = 2 * cells_[1] + 1, nk = 2 * cells_[2] + 1;
  if (i < 0 || j < 0 || k < 0 || i >= ni || j >= nj || k >= nk) return -1;
  return node_index_[static_cast<size_t>((k * nj + j) * ni + i)];
}

}  // namespace hbtrack
