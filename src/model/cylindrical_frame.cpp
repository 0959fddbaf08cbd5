#include "hbtrack/model/cylindrical_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

CylindricalFrame cylindrical_frame_about_x(const Eigen::Vector3d& position) {
  CylindricalFrame frame;
  frame.radius = std::hypot(position.y(), position.z());
  if (!(frame.radius > 0.0)) throw std::invalid_argument("cylindrical frame: the point lies on the rotation axis");
  const Eigen::Vector3d axial = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d radial(0.0, position.y() / frame.radius, position.z() / frame.radius);
  frame.directions.col(0) = radial;
  frame.directions.col(1) = axial.cross(radial);
  frame.directions.col(2) = axial;
  return frame;
}

}  // namespace hbtrack
