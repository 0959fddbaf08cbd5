#include "hbtrack/model/fe_assembly.hpp"

#include <stdexcept>
#include <string>

namespace hbtrack {

DofNumbering::DofNumbering(const std::vector<bool>& clamped) : dofs_(3 * clamped.size(), -1) {
  for (size_t node = 0; node < clamped.size(); ++node)
    if (!clamped[node])
      for (size_t d = 0; d < 3; ++d) dofs_[3 * node + d] = free_++;
}

std::vector<int> DofNumbering::free_nodes() const {
  std::vector<int> out;
  for (int node = 0; node < nodes(); ++node)
    if (dof(node, 0) >= 0) out.push_back(node);
  return out;
}

AssembledMatrices assemble_hex20(const SolidMesh& mesh, const IsotropicMaterial& material, const DofNumbering& dofs) {
  material.validate();
  if (dofs.nodes() != mesh.node_count()) throw std::invalid_argument("assembly: dof numbering does not match the mesh");
  std::vector<Eigen::Triplet<double>> k_entries, m_entries;
  const size_t per_element = static_cast<size_t>(kHex20Dofs) * kHex20Dofs;
  k_entries.reserve(mesh.elements.size() * per_element);
  m_entries.reserve(mesh.elements.size() * per_element);
  std::array<int, kHex20Dofs> global{};
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
    Hex20ElementMatrices element;
    try {
      element = hex20_element_matrices(mesh.element_coordinates(e), material);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument("element " + std::to_string(e + 1) + ": " + error.what());
    }
    const auto& connectivity = mesh.elements[static_cast<size_t>(e)];
    for (int a = 0; a < kHex20Nodes; ++a)
      for (int d = 0; d < 3; ++d) global[static_cast<size_t>(3 * a + d)] = dofs.dof(connectivity[static_cast<size_t>(a)], d);
    for (int r = 0; r < kHex20Dofs; ++r) {
      const int gr = global[static_cast<size_t>(r)];
      if (gr < 0) continue;
      for (int c = 0; c < kHex20Dofs; ++c) {
        const int gc = global[static_cast<size_t>(c)];
        if (gc < 0) continue;
        k_entries.emplace_back(gr, gc, element.stiffness(r, c));
        if (element.mass(r, c) != 0.0) m_entries.emplace_back(gr, gc, element.mass(r, c));
      }
    }
  }
  AssembledMatrices out;
  out.stiffness.resize(dofs.free_dofs(), dofs.free_dofs());
  out.mass.resize(dofs.free_dofs(), dofs.free_dofs());
  out.stiffness.setFromTriplets(k_entries.begin(), k_entries.end());  // duplicates are summed
  out.mass.setFromTriplets(m_entries.begin(), m_entries.end());
  return out;
}

}  // namespace hbtrack
