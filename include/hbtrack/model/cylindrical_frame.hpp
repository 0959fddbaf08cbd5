#pragma once
// The local frame of a point of a rotor: radial (from the rotation axis to the point,
// perpendicular to it), circumferential (axial x radial: the direction a positive rotation about
// the axis moves the point) and axial (the axis direction). The tip contact element works in
// this frame.
#include <Eigen/Dense>

namespace hbtrack {

struct CylindricalFrame {
  double radius = 0;           // distance from the rotation axis
  Eigen::Matrix3d directions;  // columns: radial, circumferential, axial unit vectors
  Eigen::Vector3d radial() const { return directions.col(0); }
  Eigen::Vector3d circumferential() const { return directions.col(1); }
  Eigen::Vector3d axial() const { return directions.col(2); }
};

// The axis passes through `origin` along `direction` (any length > 0). Throws
// std::invalid_argument for a zero direction or a point on the axis (no radial direction).
CylindricalFrame cylindrical_frame(const Eigen::Vector3d& position, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction);
// About the X axis through the origin (the generated blades' convention).
CylindricalFrame cylindrical_frame_about_x(const Eigen::Vector3d& position);

}  // namespace hbtrack
