#include "hbtrack/model/blade_sections.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hbtrack {

namespace {

[[noreturn]] void invalid(const std::string& rule) { throw std::invalid_argument("blade sections: " + rule); }

double theta_suction(const SectionPoint& p) { return p.rtheta_suction / p.radius; }
double theta_camber(const SectionPoint& p) { return (p.rtheta_suction - 0.5 * p.tangential_thickness) / p.radius; }

// The outermost surface moved inwards by `clearance`, normal to the casing in the meridional
// (x, r) plane. Over the tip the casing is a cone: its slope dr/dx is the least-squares line
// through the surface's points.
std::vector<SectionPoint> tip_section(const std::vector<SectionPoint>& casing, double clearance) {
  double mean_x = 0, mean_r = 0;
  for (const auto& p : casing) mean_x += p.axial / casing.size(), mean_r += p.radius / casing.size();
  double sxx = 0, sxr = 0;
  for (const auto& p : casing) sxx += (p.axial - mean_x) * (p.axial - mean_x), sxr += (p.axial - mean_x) * (p.radius - mean_r);
  const double slope = sxx > 0 ? sxr / sxx : 0.0;
  const double norm = std::sqrt(1.0 + slope * slope);
  std::vector<SectionPoint> tip = casing;
  for (auto& p : tip) {
    const double theta = theta_suction(p), dtheta = p.tangential_thickness / p.radius;
    p.axial += clearance * slope / norm;
    p.radius -= clearance / norm;
    p.rtheta_suction = theta * p.radius;  // same angles on the smaller radius
    p.tangential_thickness = dtheta * p.radius;
  }
  return tip;
}

}  // namespace

void BladeSections::validate() const {
  if (surfaces.size() < 2) invalid("at least 2 stream surfaces are needed (hub and tip)");
  if (surfaces.size() > kMaxStreamSurfaces) invalid("at most " + std::to_string(kMaxStreamSurfaces) + " stream surfaces");
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const auto& surface = surfaces[s];
    const std::string where = "surface " + std::to_string(s + 1) + ": ";
    if (surface.size() < 4) invalid(where + "at least 4 points are needed");
    if (surface.size() != surfaces[0].size()) invalid(where + "every surface must have as many points as the first");
    for (const auto& p : surface) {
      if (!std::isfinite(p.axial) || !std::isfinite(p.radius) || !std::isfinite(p.rtheta_suction) || !std::isfinite(p.tangential_thickness))
        invalid(where + "values must be finite");
      if (!(p.radius > 0)) invalid(where + "radius must be > 0");
      if (p.tangential_thickness < 0) invalid(where + "tangential thickness must be >= 0");
    }
  }
  if (blade_count < 1 || blade_count > kMaxBladeCount) invalid("blade count must be in 1.." + std::to_string(kMaxBladeCount));
}

RotationSense rotation_sense(const BladeSections& sections) {
  sections.validate();
  const auto& tip = sections.surfaces.back();
  RotationSense r;
  const SectionPoint &le = tip.front(), &te = tip.back();
  r.leading_edge_lead = (theta_camber(le) - theta_camber(te)) * 0.5 * (le.radius + te.radius);
  // The pressure surface is the suction surface less the thickness: at smaller theta.
  double thickness = 0;
  for (const auto& p : tip) thickness += p.tangential_thickness;
  r.pressure_side = thickness > 0 ? -1 : 0;
  const int leading = r.leading_edge_lead > 0 ? 1 : (r.leading_edge_lead < 0 ? -1 : 0);
  if (leading == 0 || r.pressure_side == 0 || leading != r.pressure_side)
    invalid("the leading edge leads towards " + std::to_string(leading) + " theta but the pressure surface faces " +
            std::to_string(r.pressure_side) + ": not the blade of a compressor rotor");
  r.sense = leading;
  return r;
}

Eigen::Vector3d cartesian_point(double axial, double radius, double theta) {
  return {axial, radius * std::cos(theta), radius * std::sin(theta)};
}

SectionBladeShape::SectionBladeShape(const BladeSections& sections, const SectionBladeShapeOptions& options) : options_(options) {
  sections.validate();
  if (!(options.tip_clearance >= 0) || !(options.minimum_thickness >= 0)) invalid("tip clearance and minimum thickness must be >= 0");
  for (size_t s = 0; s < sections.surfaces.size(); ++s) {
    const bool tip = s + 1 == sections.surfaces.size();
    const auto points = tip ? tip_section(sections.surfaces[s], options.tip_clearance) : sections.surfaces[s];
    const auto n = static_cast<Eigen::Index>(points.size());
    Eigen::MatrixXd values(n, 4);
    Eigen::VectorXd length = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto& p = points[static_cast<size_t>(i)];
      values.row(i) << p.axial, p.radius, theta_camber(p), p.tangential_thickness / p.radius;
      if (i > 0) {
        const Eigen::Vector3d a = cartesian_point(values(i - 1, 0), values(i - 1, 1), values(i - 1, 2));
        const Eigen::Vector3d b = cartesian_point(values(i, 0), values(i, 1), values(i, 2));
        length(i) = length(i - 1) + (b - a).norm();
      }
    }
    if (!(length(n - 1) > 0)) invalid("surface " + std::to_string(s + 1) + ": the camber line has zero length");
    for (Eigen::Index i = 1; i < n; ++i)
      if (!(length(i) > length(i - 1))) invalid("surface " + std::to_string(s + 1) + ": two consecutive points coincide");
    fractions_.push_back(length / length(n - 1));
    per_surface_.emplace_back(fractions_.back(), values);
  }
}

Eigen::Vector4d SectionBladeShape::camber(double u, double sigma) const {
  const auto count = static_cast<Eigen::Index>(per_surface_.size());
  Eigen::VectorXd levels(count);
  Eigen::MatrixXd at_u(count, 4);
  for (Eigen::Index s = 0; s < count; ++s) {
    levels(s) = static_cast<double>(s);
    at_u.row(s) = per_surface_[static_cast<size_t>(s)](u);
  }
  // At a surface itself no interpolation across surfaces (exact published points).
  const double nearest = std::round(sigma);
  if (std::abs(sigma - nearest) < 1e-12 && nearest >= 0 && nearest < count) return at_u.row(static_cast<Eigen::Index>(nearest)).transpose();
  return NaturalCubicSpline(levels, at_u)(sigma).transpose();
}

Eigen::Vector3d SectionBladeShape::point(double u, double v, double sigma) const {
  const Eigen::Vector4d c = camber(u, sigma);
  const double dtheta = std::max(c(3), options_.minimum_thickness / c(1));
  // v = 0 on the suction surface (larger theta), 1 on the pressure surface: with u along the
  // chord and sigma outwards this keeps every element's Jacobian positive.
  return cartesian_point(c(0), c(1), c(2) + (0.5 - v) * dtheta);
}

}  // namespace hbtrack
