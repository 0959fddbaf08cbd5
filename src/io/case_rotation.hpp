#pragma once
// [rotation] speed = Omega (rad/s, a number or a named parameter), with [model] Kg1, Mspin and
// optionally G: the linear model at that speed, K(Omega) = K + Omega^2 (Kg1 - Mspin) and
// C + Omega G (model/rotating_matrices.hpp).
#include "case_reader.hpp"

namespace hbtrack {

// After [model], before [damping] (modal ratios refer to the modes at speed): replaces the model's
// stiffness by K(Omega).
void read_rotation(const CaseReader& in, const toml::value& root, CaseDefinition& c);
// After [damping]: adds Omega G to C.
void add_gyroscopic_damping(CaseDefinition& c);
// After [parameters]: the speed's parameter cannot be varied by a continuation.
void fix_rotation_parameter(CaseDefinition& c);

}  // namespace hbtrack
