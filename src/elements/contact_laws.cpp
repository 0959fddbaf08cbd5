#include "hbtrack/elements/contact_laws.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

ContactLawKind parse_contact_law(const std::string& name) {
  if (name == "penalty") return ContactLawKind::penalty;
  if (name == "polynomial") return ContactLawKind::polynomial;
  if (name == "sqrt") return ContactLawKind::sqrt;
  throw std::invalid_argument("unknown contact law '" + name + "' (expected penalty, polynomial or sqrt)");
}

std::string to_string(ContactLawKind kind) {
  switch (kind) {
    case ContactLawKind::penalty:
      return "penalty";
    case ContactLawKind::polynomial:
      return "polynomial";
    case ContactLawKind::sqrt:
      return "sqrt";
  }
  return "?";
}

std::string smoothness_limit(ContactLawKind kind) {
  switch (kind) {
    case ContactLawKind::penalty:
      return "law \"penalty\" is only C0";
    case ContactLawKind::polynomial:
      return "law \"polynomial\" is only C1";
    case ContactLawKind::sqrt:
      return "";
  }
  return "";
}

ContactForce contact_force(ContactLawKind kind, double g, double k, double width) {
  ContactForce out;
  const double s = k * g;  // the force the plain penalty law would give
  double df_ds = 0.0;
  if (kind == ContactLawKind::penalty || width <= 0.0) {
    if (s > 0.0) {
      out.force = s;
      df_ds = 1.0;
    }
  } else if (kind == ContactLawKind::polynomial) {
    if (s >= width) {
      out.force = s;
      df_ds = 1.0;
    } else if (s > -width) {
      // Quadratic blend: matches value and slope of 0 at s = -width and of s at s = +width.
      const double u = s + width;
      out.force = u * u / (4.0 * width);
      df_ds = u / (2.0 * width);
      out.d_width = u / (2.0 * width) - u * u / (4.0 * width * width);
    }
  } else {  // sqrt
    const double root = std::sqrt(s * s + width * width);
    out.force = 0.5 * (s + root);
    df_ds = 0.5 * (1.0 + s / root);
    out.d_width = 0.5 * width / root;
  }
  out.d_gap = df_ds * k;
  out.d_stiffness = df_ds * g;
  return out;
}

}  // namespace hbtrack
