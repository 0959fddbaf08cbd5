#include "hbtrack/model/section_blade.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbtrack {

namespace {

// The rim sector under the hub at depth fraction rho in (0, 1]: the hub's camber line moved
// radially inwards, the airfoil's tangential width opening to the blade pitch over the first
// of `layers` element layers.
Eigen::Vector3d rim_point(const SectionBladeShape& shape, double pitch, double depth, int layers, const Eigen::Vector3d& unit, double rho) {
  const Eigen::Vector4d hub = shape.camber(unit.x(), 0.0);
  const double airfoil_width = std::max(hub(3), shape.minimum_thickness() / hub(1));
  const double opening = std::min(1.0, rho * layers);
  const double width = airfoil_width + (pitch - airfoil_width) * opening;
  return cartesian_point(hub(0), hub(1) - rho * depth, hub(2) + (0.5 - unit.y()) * width);
}

}  // namespace

void SectionBladeOptions::validate() const {
  if (chord_elements < 4 || chord_elements % 4 != 0)
    throw std::invalid_argument("section blade: chord_elements must be a positive multiple of 4");
  if (thickness_elements < 2 || thickness_elements % 2 != 0) throw std::invalid_argument("section blade: thickness_elements must be even");
  if (span_elements_per_surface < 1) throw std::invalid_argument("section blade: span_elements_per_surface must be >= 1");
  if (refinement < 1 || refinement > 16) throw std::invalid_argument("section blade: refinement must be in 1..16");
  if (!(rim_depth >= 0) || !std::isfinite(rim_depth)) throw std::invalid_argument("section blade: rim_depth must be >= 0");
  if (rim_depth > 0 && rim_elements < 1) throw std::invalid_argument("section blade: rim_elements must be >= 1");
  material.validate();
}

SectionBlade generate_section_blade(const BladeSections& sections, const SectionBladeOptions& options) {
  options.validate();
  // Checked before meshing (a wrong table fails fast) and not inside the aggregate below: GCC 12
  // destroys the moved-in base twice when a later initializer throws (PR 66139).
  const RotationSense rotation = rotation_sense(sections);
  const SectionBladeShape shape(sections, options.shape);
  const int r = options.refinement;
  const int rim_layers = options.rim_depth > 0 ? options.rim_elements * r : 0;
  const int airfoil_layers = (shape.surfaces() - 1) * options.span_elements_per_surface * r;
  const std::array<int, 3> cells{options.chord_elements * r, options.thickness_elements * r, rim_layers + airfoil_layers};
  const long elements = long{cells[0]} * cells[1] * cells[2];
  if (elements > kMaxSectionBladeElements)
    throw std::invalid_argument("section blade: " + std::to_string(elements) +
                                " elements (surfaces x refinement), more than the limit of " + std::to_string(kMaxSectionBladeElements));
  const double hub_level = double(rim_layers) / cells[2];  // unit-cube span coordinate of the hub
  const double pitch = 2.0 * std::numbers::pi / sections.blade_count;
  StructuredHex20Grid grid(cells, [&](const Eigen::Vector3d& unit) -> Eigen::Vector3d {
    if (unit.z() >= hub_level) {
      const double sigma = (unit.z() - hub_level) / (1.0 - hub_level) * (shape.surfaces() - 1);
      return shape.point(unit.x(), unit.y(), sigma);
    }
    return rim_point(shape, pitch, options.rim_depth, rim_layers, unit, (hub_level - unit.z()) / hub_level);
  });
  DofNumbering dofs(root_face_clamped(grid));
  SectionBlade blade{{options.material, std::move(grid), std::move(dofs), {}, {}, {}, {}, {}, {}, {}}, rotation, rim_layers};
  find_blade_lines(blade, 2 * rim_layers);
  return blade;
}

}  // namespace hbtrack
