#pragma once
// Normal contact laws f_N(g) for a penetration g (g > 0: penetration), regularising
// max(0, k g). All are C0 or C1 in g and return analytic derivatives.
#include <string>

namespace hbtrack {

enum class ContactLawKind {
  penalty,     // f = k max(0, g): C0, the unilateral spring
  polynomial,  // C1 quadratic blend of half-width `width` (force units) around k g = 0 (method notes 3)
  sqrt,        // f = (k g + sqrt((k g)^2 + width^2)) / 2: C-infinity hyperbolic smoothing
};

ContactLawKind parse_contact_law(const std::string& name);  // throws std::invalid_argument
std::string to_string(ContactLawKind kind);
// "" for the C-infinity sqrt law, otherwise e.g. "law \"penalty\" is only C0".
std::string smoothness_limit(ContactLawKind kind);

struct ContactForce {
  double force = 0;  // f_N
  double d_gap = 0;  // d f_N / d g
  double d_stiffness = 0;
  double d_width = 0;
};

// Normal force for penetration `gap_penetration`, penalty `stiffness`, regularisation `width`.
ContactForce contact_force(ContactLawKind kind, double gap_penetration, double stiffness, double width);

}  // namespace hbtrack
