#include "hbtrack/model/calculix_deck.hpp"

#include <sstream>

namespace hbtrack {

std::string calculix_deck(const SolidMesh& mesh, const std::vector<int>& clamped_nodes, const IsotropicMaterial& material,
                          const std::string& step) {
  std::ostringstream deck;
  deck.precision(14);  // ccx reads at most 20 characters per field
  deck << "** written by hbtrack: " << mesh.node_count() << " nodes, " << mesh.elements.size() << " C3D20 elements\n*NODE, NSET=NALL\n";
  for (int n = 0; n < mesh.node_count(); ++n) {
    const auto& p = mesh.nodes[static_cast<size_t>(n)];
    deck << n + 1 << ", " << p.x() << ", " << p.y() << ", " << p.z() << "\n";
  }
  deck << "*ELEMENT, TYPE=C3D20, ELSET=EALL\n";
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    deck << e + 1;
    // ccx takes at most 16 entries on a line: the element number and 15 nodes, then 5 more.
    for (size_t a = 0; a < mesh.elements[e].size(); ++a) deck << (a == 15 ? ",\n" : ", ") << mesh.elements[e][a] + 1;
    deck << "\n";
  }
  if (!clamped_nodes.empty()) {
    deck << "*BOUNDARY\n";
    for (int n : clamped_nodes) deck << n + 1 << ", 1, 3\n";
  }
  deck << "*MATERIAL, NAME=MAT\n*ELASTIC\n"
       << material.youngs_modulus << ", " << material.poisson_ratio << "\n*DENSITY\n"
       << material.density << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=MAT\n";
  deck << "*STEP\n" << step << "\n*END STEP\n";
  return deck.str();
}

}  // namespace hbtrack
