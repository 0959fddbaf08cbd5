#pragma once
// The identity of the model a run computes: an FNV-1a hash of its dof names, mass, damping and
// stiffness matrices, forcing, and nonlinear elements (type, dofs, property bindings, Lanczos,
// and what a subclass keeps of its own: NonlinearElement::configuration). Written
// into summary.json's options, and so into every checkpoint's settings: a --resume whose model
// was edited since (a stiffness in K.mtx, a forcing, a damping ratio) is refused instead of
// continuing one branch on two systems.
#include <string>

#include "hbtrack/elements/nonlinear_element.hpp"
#include "hbtrack/model/structural_model.hpp"

namespace hbtrack {

// 16 hex digits; equal models (bit for bit) give equal strings on every machine of the same
// endianness.
std::string model_fingerprint(const StructuralModel& model, const ElementList& elements);

}  // namespace hbtrack
