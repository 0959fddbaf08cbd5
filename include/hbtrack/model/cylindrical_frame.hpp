#pragma once
// The local frame of a point of a rotor whose rotation axis is X: radial (from the axis to the
// point, perpendicular to X), circumferential (axial x radial) and axial (X). The tip contact
// element works in this frame.
#include <Eigen/Dense>

namespace hbtrack {

struct CylindricalFrame {
  double radius = 0;                // distance from the rotation axis
  Eigen::Matrix3d directions;       // columns: radial, circumferential, axial unit vectors
  Eigen::Vector3d radial() const { return directions.col(0); }
  Eigen::Vector3d circumferential() const { return directions.col(1); }
  Eigen::Vector3d axial() const { return directions.col(2); }
};

// Throws std::invalid_argument for a point on the axis (no radial direction).
CylindricalFrame cylindrical_frame_about_x(const Eigen::Vector3d& position);

}  // namespace hbtrack
