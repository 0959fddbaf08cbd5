#pragma once
// A blade given by its sections on stream surfaces, hub to casing, as NASA publishes rotor 67
// (data/rotor67/sections.csv, derived from NASA's file by scripts/derive-rotor67-sections.py):
// per surface, points from the leading to the trailing edge with their axial position, radius,
// r*theta of the suction surface and tangential thickness r*dtheta (pressure = suction - thickness).
// X is the rotation axis and a point (x, r, theta) sits at (x, r cos theta, r sin theta), so
// +theta is the circumferential direction of cylindrical_frame_about_x. Metres.
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/util/cubic_spline.hpp"

namespace hbtrack {

struct SectionPoint {
  double axial = 0, radius = 0, rtheta_suction = 0, tangential_thickness = 0;
};

// Far above any rotor (rotor 67: 14 surfaces, 22 blades); a larger table is a wrong file, and the
// span elements (one layer per gap between surfaces) grow with the surfaces.
inline constexpr int kMaxStreamSurfaces = 100;
inline constexpr int kMaxBladeCount = 1000;

struct BladeSections {
  std::vector<std::vector<SectionPoint>> surfaces;  // hub (0) to casing; each leading to trailing edge
  int blade_count = 0;                              // blades on the rotor (the disk sector's pitch)
  // Throws std::invalid_argument naming the rule broken (fewer than 2 surfaces or 4 points, a
  // negative thickness or radius, a non-finite value, surfaces of different point counts,
  // more than kMaxStreamSurfaces surfaces, a blade count outside 1..kMaxBladeCount).
  void validate() const;
};

// The sense of rotation read from the geometry. An axial compressor rotor turns so that its
// leading edge leads and its pressure surface faces the direction of motion: both are measured
// on the tip section and must agree. `sense` is +1 when the blade moves towards +theta (the
// circumferential direction of the tip frames), -1 towards -theta.
struct RotationSense {
  int sense = 0;
  double leading_edge_lead = 0;  // (theta_LE - theta_TE) * r at the tip (m): > 0 when LE is at +theta
  int pressure_side = 0;         // the circumferential side the pressure surface faces (+1 / -1)
};
// Throws std::invalid_argument when the two criteria disagree (not a compressor rotor's blade).
RotationSense rotation_sense(const BladeSections& sections);

// What the mesh generator does with the sections.
struct SectionBladeShapeOptions {
  double tip_clearance = 0;      // m: the tip is the outermost surface less this, normal to it
  double minimum_thickness = 0;  // m: the tangential thickness is floored to this (thin edges)
};

// The blade's shape as a map from (chord fraction u, thickness fraction v, span level sigma) to
// space. u in [0, 1] is arc length along the camber line from the leading edge; v in [0, 1] goes
// from the suction to the pressure surface; sigma in [0, surfaces - 1] is the stream surface
// index from the hub (sigma = 0), the last being the tip. Sections are natural cubic splines in
// u per surface and in sigma across surfaces, so the map reproduces every published point at
// integer sigma.
class SectionBladeShape {
 public:
  SectionBladeShape(const BladeSections& sections, const SectionBladeShapeOptions& options);
  // (axial, radius, theta of the camber line, tangential thickness as an angle) at (u, sigma).
  Eigen::Vector4d camber(double u, double sigma) const;
  Eigen::Vector3d point(double u, double v, double sigma) const;
  int surfaces() const { return static_cast<int>(per_surface_.size()); }
  // Chord fraction of every published point of surface `s`, leading to trailing edge.
  const Eigen::VectorXd& point_fractions(int s) const { return fractions_[static_cast<size_t>(s)]; }
  double minimum_thickness() const { return options_.minimum_thickness; }

 private:
  SectionBladeShapeOptions options_;
  std::vector<NaturalCubicSpline> per_surface_;  // u -> (x, r, theta_camber, dtheta)
  std::vector<Eigen::VectorXd> fractions_;
};

Eigen::Vector3d cartesian_point(double axial, double radius, double theta);

}  // namespace hbtrack
