#include "hbtrack/model/blade_mode_classifier.hpp"

#include <cmath>
#include <stdexcept>

namespace hbtrack {

namespace {

// Values below this fraction of the largest are treated as zero when counting sign changes:
// round-off and the tiny motion near the clamped root must not count as a nodal line.
constexpr double kSignThreshold = 0.05;

Eigen::Vector3d displacement(const BladeMesh& blade, const Eigen::VectorXd& shape, int node) {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const int dof = blade.dofs.dof(node, k);
    if (dof >= 0) d(k) = shape(dof);
  }
  return d;
}

int sign_changes(const Eigen::VectorXd& values) {
  const double threshold = kSignThreshold * values.cwiseAbs().maxCoeff();
  int changes = 0, last_sign = 0;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (std::abs(values(i)) <= threshold) continue;
    const int sign = values(i) > 0 ? 1 : -1;
    if (last_sign != 0 && sign != last_sign) ++changes;
    last_sign = sign;
  }
  return changes;
}

}  // namespace

std::string BladeModeType::label() const { return family == '?' ? "?" : std::to_string(order) + family; }

BladeModeType classify_blade_mode(const BladeMesh& blade, const Eigen::VectorXd& shape) {
  if (shape.size() != blade.dofs.free_dofs()) throw std::invalid_argument("blade mode: shape size does not match the blade's dofs");
  const Eigen::Vector3d normal = blade.station_normal.back(), chord = blade.station_chord.back();
  const auto tip_count = static_cast<Eigen::Index>(blade.tip_nodes.size());
  Eigen::VectorXd out_of_plane(tip_count);
  double flap = 0, edge = 0, all = 0;
  for (Eigen::Index j = 0; j < tip_count; ++j) {
    const Eigen::Vector3d d = displacement(blade, shape, blade.tip_nodes[static_cast<size_t>(j)]);
    out_of_plane(j) = d.dot(normal);
    flap += out_of_plane(j) * out_of_plane(j);
    edge += d.dot(chord) * d.dot(chord);
    all += d.squaredNorm();
  }
  BladeModeType type;
  // A mode that hardly moves the tip in the section plane (radial/extensional) has no family here.
  if (!(all > 0) || flap + edge < 0.5 * all) return type;

  const auto stations = static_cast<Eigen::Index>(blade.mid_chord_line.size());
  Eigen::VectorXd along_span(stations);
  for (Eigen::Index k = 0; k < stations; ++k) {
    const auto station = static_cast<size_t>(k);
    const Eigen::Vector3d& n = blade.station_normal[station];
    const Eigen::Vector3d& c = blade.station_chord[station];
    if (flap < edge) {
      type.family = 'E';
      along_span(k) = displacement(blade, shape, blade.mid_chord_line[station]).dot(c);
    } else if (sign_changes(out_of_plane) == 0) {
      type.family = 'B';
      along_span(k) = displacement(blade, shape, blade.mid_chord_line[station]).dot(n);
    } else {
      type.family = 'T';  // twist: leading edge minus trailing edge out-of-plane motion
      along_span(k) =
          (displacement(blade, shape, blade.leading_edge_line[station]) - displacement(blade, shape, blade.trailing_edge_line[station]))
              .dot(n);
    }
  }
  type.order = 1 + sign_changes(along_span);
  return type;
}

}  // namespace hbtrack
