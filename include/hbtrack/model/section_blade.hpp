#pragma once
// A fan blade meshed from its published stream-surface sections (blade_sections.hpp): 20-node
// hexahedra, chord x thickness x span, from the hub section to the tip (the casing surface less
// the running clearance), optionally standing on a one-pitch sector of the disk rim that is
// clamped at its bottom face; without the rim the hub section itself is clamped.
#include "hbtrack/model/blade_mesh.hpp"
#include "hbtrack/model/blade_sections.hpp"

namespace hbtrack {

// A mesh of more elements is refused before it is built: its modes would take hours (rotor 67 at
// --refine 4 has 34 816).
inline constexpr long kMaxSectionBladeElements = 50'000;

struct SectionBladeOptions {
  // NASA's running clearance at 100 % speed, 0.024 inch, and a tangential thickness floor at
  // the edges (where the published thickness goes to zero) of 0.5 mm.
  SectionBladeShapeOptions shape{0.024 * 0.0254, 0.5e-3};
  IsotropicMaterial material{108e9, 0.34, 4400.0};  // TA6V (the paper's Table 1)
  // Elements along the chord (a multiple of 4: 9 tip nodes), through the thickness (even), and
  // along the span per gap between stream surfaces; all multiplied by `refinement`.
  int chord_elements = 16, thickness_elements = 2, span_elements_per_surface = 1;
  int refinement = 1;
  // The root: a sector of the disk rim of one blade pitch (2 pi / blade count) under the hub
  // section, `rim_depth` deep (m), clamped at its bottom. Its first element layer widens the
  // airfoil to the full pitch (a coarse fillet and platform). 0: the hub section is clamped.
  double rim_depth = 0.02;
  int rim_elements = 4;   // element layers in the rim (times `refinement`)
  void validate() const;  // throws std::invalid_argument
};

struct SectionBlade : BladeMesh {
  RotationSense rotation;
  int rim_layers = 0;  // span element layers below the hub
};

SectionBlade generate_section_blade(const BladeSections& sections, const SectionBladeOptions& options);

}  // namespace hbtrack
