#include "hbtrack/model/cylindrical_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

CylindricalFrame cylindrical_frame(const Eigen::Vector3d& position, const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  const double length = direction.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("cylindrical frame: the axis direction must be a finite, nonzero vector");
  const Eigen::Vector3d axial = direction / length;
  const Eigen::Vector3d offset = position - origin;
  const Eigen::Vector3d off_axis = offset - offset.dot(axial) * axial;
  CylindricalFrame frame;
  frame.radius = off_axis.norm();
  // Relative to the point's distance from the origin: a point this close sits on the axis.
  if (!(frame.radius > 1e-12 * std::max(1.0, offset.norm())))
    throw std::invalid_argument("cylindrical frame: the point lies on the rotation axis");
  const Eigen::Vector3d radial = off_axis / frame.radius;
  frame.directions.col(0) = radial;
  frame.directions.col(1) = axial.cross(radial);
  frame.directions.col(2) = axial;
  return frame;
}

CylindricalFrame cylindrical_frame_about_x(const Eigen::Vector3d& position) {
  return cylindrical_frame(position, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX());
}

}  // namespace hbtrack
