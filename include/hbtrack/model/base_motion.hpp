#pragma once
// Imposed harmonic base (support) motion, in relative coordinates. The dofs in `dofs` are carried
// by the base with influence 1 (r_i = 1: the base moves them rigidly in their direction); the
// unknowns are the motion relative to the base, x = x_abs - r u_b, and the springs, dampers and
// grounded elements of the model act between the dofs and the base. With K r = C r = 0 for the
// unconstrained structure (the base carries the whole support), the equation of motion becomes
//   M x'' + C x' + K x + f_nl(x, x') = -M r u_b''(t),
// a forcing that grows as (h omega)^2 for an imposed displacement, h omega for a velocity and is
// fixed for an acceleration.
#include <string>
#include <vector>

#include "hbtrack/model/structural_model.hpp"
#include "hbtrack/util/choices.hpp"

namespace hbtrack {

struct BaseMotion {
  BaseMotionKind kind = BaseMotionKind::displacement;
  std::vector<int> dofs;  // indices of the dofs the base carries (influence 1)
  int harmonic = 1;       // h: the base moves at h omega
  // u_b(t) = cos_part cos(h w t) + sin_part sin(h w t) for a displacement, the same for a velocity
  // u_b'(t) or an acceleration u_b''(t); scaled by the parameter `amplitude` like any forcing.
  double cos_part = 0.0, sin_part = 0.0;
};

// The equivalent forcing -M r u_b'' as one HarmonicForce and the growth that multiplies it:
// (omega / omega_ref)^k, k = 2, 1, 0 for displacement, velocity, acceleration. omega_ref is the
// model's lowest undamped frequency (1 rad/s when it has none > 0): there the force is its size
// near the first resonance, which keeps the continuation's force scale representative.
struct EquivalentForcing {
  HarmonicForce force;
  ForcingGrowth growth;
};
// Throws std::invalid_argument naming the rule (a dof out of range, harmonic < 1).
EquivalentForcing base_motion_forcing(const StructuralModel& model, const BaseMotion& base);

}  // namespace hbtrack
