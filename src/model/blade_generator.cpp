#include "hbtrack/model/blade_generator.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbtrack {

namespace {

double lerp(double root, double tip, double s) { return root + s * (tip - root); }

double stagger(const BladeGeometry& g, double s) { return lerp(g.root_stagger_deg, g.tip_stagger_deg, s) * std::numbers::pi / 180.0; }

// The point at chord fraction u, thickness fraction v, span fraction s (all in [0, 1]).
Eigen::Vector3d blade_point(const BladeGeometry& g, const Eigen::Vector3d& unit) {
  const double u = unit.x(), v = unit.y(), s = unit.z();
  const double chord = lerp(g.root_chord, g.tip_chord, s);
  const double along = (u - 0.5) * chord;  // from mid-chord, leading edge negative
  const double camber_offset = g.camber * chord * (1.0 - 4.0 * (u - 0.5) * (u - 0.5));
  // Thickness fraction v runs against the normal so that (chord, thickness, span) is right-handed
  // and every element has a positive Jacobian.
  const double across = (0.5 - v) * lerp(g.root_thickness, g.tip_thickness, s) + camber_offset;
  const double beta = stagger(g, s);
  // Chord along (cos b, 0, sin b), thickness normal along (-sin b, 0, cos b), in (X, Y, Z).
  return {along * std::cos(beta) - across * std::sin(beta), lerp(g.hub_radius, g.tip_radius, s),
          along * std::sin(beta) + across * std::cos(beta)};
}

}  // namespace

void BladeGeometry::validate() const {
  auto positive = [](double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value)) throw std::invalid_argument(std::string("blade geometry: ") + name + " must be > 0");
  };
  positive(hub_radius, "hub_radius");
  positive(span(), "tip_radius - hub_radius");
  positive(root_chord, "root_chord");
  positive(tip_chord, "tip_chord");
  positive(root_thickness, "root_thickness");
  positive(tip_thickness, "tip_thickness");
  if (!std::isfinite(root_stagger_deg) || !std::isfinite(tip_stagger_deg) || !std::isfinite(camber))
    throw std::invalid_argument("blade geometry: stagger angles and camber must be finite");
  if (chord_elements != 4) throw std::invalid_argument("blade geometry: chord_elements must be 4 (9 tip nodes)");
  if (thickness_elements < 2 || thickness_elements % 2 != 0)
    throw std::invalid_argument("blade geometry: thickness_elements must be even (mid-thickness nodes)");
  if (span_elements < 1) throw std::invalid_argument("blade geometry: span_elements must be >= 1");
  material.validate();
}

Eigen::Vector3d BladeModel::chord_direction(double s) const {
  const double beta = stagger(geometry, s);
  return {std::cos(beta), 0.0, std::sin(beta)};
}

Eigen::Vector3d BladeModel::out_of_plane_direction(double s) const {
  const double beta = stagger(geometry, s);
  return {-std::sin(beta), 0.0, std::cos(beta)};
}

double BladeModel::span_fraction(int node) const {
  return (grid.mesh().nodes[static_cast<size_t>(node)].y() - geometry.hub_radius) / geometry.span();
}

BladeModel generate_blade(const BladeGeometry& geometry, int refinement) {
  geometry.validate();
  if (refinement < 1) throw std::invalid_argument("blade: refinement must be >= 1");
  const std::array<int, 3> cells{geometry.chord_elements * refinement, geometry.thickness_elements * refinement,
                                 geometry.span_elements * refinement};
  StructuredHex20Grid grid(cells, [&](const Eigen::Vector3d& unit) { return blade_point(geometry, unit); });
  DofNumbering dofs(root_face_clamped(grid));
  BladeModel blade{{geometry.material, std::move(grid), std::move(dofs), {}, {}, {}, {}, {}, {}, {}}, geometry, refinement};
  find_blade_lines(blade, 0);
  return blade;
}

}  // namespace hbtrack
