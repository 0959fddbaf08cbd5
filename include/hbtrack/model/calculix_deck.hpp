#pragma once
// A solid mesh as a CalculiX (ccx) input deck, so that a model built here can be checked with, or
// reduced from the matrices of, CalculiX: *NODE (id = node index + 1), *ELEMENT TYPE=C3D20
// (hbtrack's hex20 node order is ccx's), the listed nodes clamped, one isotropic material, then
// the given step lines inside *STEP ... *END STEP.
#include <string>
#include <vector>

#include "hbtrack/model/elastic_material.hpp"
#include "hbtrack/model/solid_mesh.hpp"

namespace hbtrack {

// The step that makes ccx write the stiffness and mass matrices (JOB.sti, JOB.mas, JOB.dof)
// that `hbtrack reduce --calculix JOB` reads.
inline const char* kCalculixMatrixStorageStep = "*FREQUENCY, SOLVER=MATRIXSTORAGE";

// The deck's text; `step` holds the step's keyword and data lines (e.g. "*FREQUENCY\n12").
std::string calculix_deck(const SolidMesh& mesh, const std::vector<int>& clamped_nodes, const IsotropicMaterial& material,
                          const std::string& step);

}  // namespace hbtrack
