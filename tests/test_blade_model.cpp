// The parametric blade: geometry of the tip nodes and their frames, the mode classifier on
// synthetic shapes, and the shipped mesh's first three modes against the paper's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/blade_mode_classifier.hpp"
#include "hbtrack/model/sparse_modes.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_blade_model {

namespace {

using namespace hbtrack;

// The paper's rotor 67: 1B, 2B, 1T (rad/s).
constexpr double kPaper[] = {2039.78, 6343.69, 10745.26};

BladeGeometry coarse_geometry() {
  BladeGeometry g;
  g.span_elements = 4;
  return g;
}

// A shape that moves every node by `field(s, chord offset)` along a direction of its section.
template <class Field>
Eigen::VectorXd synthetic_shape(const BladeModel& blade, bool chordwise, Field field) {
  Eigen::VectorXd shape = Eigen::VectorXd::Zero(blade.dofs.free_dofs());
  const auto& nodes = blade.grid.mesh().nodes;
  for (int n = 0; n < blade.grid.mesh().node_count(); ++n) {
    if (blade.dofs.dof(n, 0) < 0) continue;
    const double s = blade.span_fraction(n);
    const double offset = nodes[static_cast<size_t>(n)].dot(blade.chord_direction(s));  // from the stacking line
    const Eigen::Vector3d direction = chordwise ? blade.chord_direction(s) : blade.out_of_plane_direction(s);
    for (int d = 0; d < 3; ++d) shape(blade.dofs.dof(n, d)) = field(s, offset) * direction(d);
  }
  return shape;
}

TEST(BladeGenerator, NineTipNodesFromLeadingToTrailingEdgeWithCylindricalFrames) {
  const BladeModel blade = generate_blade(coarse_geometry());
  ASSERT_EQ(blade.tip_nodes.size(), 9u);
  const auto& nodes = blade.grid.mesh().nodes;
  const Eigen::Vector3d chord = blade.chord_direction(1.0);
  for (size_t j = 0; j < 9; ++j) {
    const Eigen::Vector3d p = nodes[static_cast<size_t>(blade.tip_nodes[j])];
    EXPECT_NEAR(p.y(), blade.geometry.tip_radius, 1e-12);
    // Evenly spaced along the chord at mid-thickness, leading edge (upstream, -X) first.
    EXPECT_NEAR(p.dot(chord), (double(j) / 8.0 - 0.5) * blade.geometry.tip_chord, 1e-12);
    // Mid-thickness lies on the camber arc: offset c h (1 - (2u - 1)^2) out of the chord plane.
    const double u = double(j) / 8.0;
    const double camber_offset = blade.geometry.camber * blade.geometry.tip_chord * (1.0 - (2 * u - 1) * (2 * u - 1));
    EXPECT_NEAR(p.dot(blade.out_of_plane_direction(1.0)), camber_offset, 1e-12);
    const CylindricalFrame& f = blade.tip_frames[j];
    EXPECT_NEAR(f.radius, std::hypot(p.y(), p.z()), 1e-14);
    EXPECT_LT((f.directions.transpose() * f.directions - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_NEAR(f.directions.determinant(), 1.0, 1e-14);
    EXPECT_NEAR(f.radial().x(), 0.0, 1e-15);
    EXPECT_LT((f.radial() * f.radius - Eigen::Vector3d(0, p.y(), p.z())).norm(), 1e-14);
    EXPECT_EQ(f.axial(), Eigen::Vector3d::UnitX());
  }
  EXPECT_LT(nodes[static_cast<size_t>(blade.tip_nodes.front())].x(), nodes[static_cast<size_t>(blade.tip_nodes.back())].x());
  // The root face is clamped: 4 x 2 elements of serendipity nodes = 5 x 3 corners + 4 x 3 + 5 x 2 mid-edges.
  EXPECT_EQ(blade.dofs.free_dofs(), 3 * (blade.grid.mesh().node_count() - 37));
}

TEST(BladeModeClassifier, NamesSyntheticShapes) {
  const BladeModel blade = generate_blade(coarse_geometry());
  const double pi = std::numbers::pi;
  EXPECT_EQ(classify_blade_mode(blade, synthetic_shape(blade, false, [](double s, double) { return s * s; })).label(), "1B");
  EXPECT_EQ(classify_blade_mode(blade, synthetic_shape(blade, false, [&](double s, double) { return std::sin(1.5 * pi * s); })).label(),
            "2B");
  EXPECT_EQ(
      classify_blade_mode(blade, synthetic_shape(blade, false, [&](double s, double c) { return c * std::sin(0.5 * pi * s); })).label(),
      "1T");
  EXPECT_EQ(
      classify_blade_mode(blade, synthetic_shape(blade, false, [&](double s, double c) { return c * std::sin(1.5 * pi * s); })).label(),
      "2T");
  EXPECT_EQ(classify_blade_mode(blade, synthetic_shape(blade, true, [](double s, double) { return s * s; })).label(), "1E");
  EXPECT_EQ(classify_blade_mode(blade, Eigen::VectorXd::Zero(blade.dofs.free_dofs())).label(), "?");
}

TEST(BladeGenerator, ShippedMeshHasThePapersFirstThreeModes) {
  // The shipped mesh (4 x 2 x 12 elements, 1872 dofs) builds and solves in well under a second.
  const BladeModel blade = generate_blade(BladeGeometry{});
  const AssembledMatrices m = assemble_blade(blade);
  const NormalModes modes = lowest_sparse_modes(m.stiffness, m.mass, 3);
  const char* expected[] = {"1B", "2B", "1T"};
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(modes.frequencies(r) / kPaper[r], 1.0, 0.05) << expected[r];
    EXPECT_EQ(classify_blade_mode(blade, modes.shapes.col(r)).label(), expected[r]);
  }
}

TEST(BladeGenerator, CoarseMeshKeepsTheModeOrder) {
  // 4 span elements: frequencies move by a few per cent, the mode types stay.
  const BladeModel blade = generate_blade(coarse_geometry());
  const AssembledMatrices m = assemble_blade(blade);
  const NormalModes modes = lowest_sparse_modes(m.stiffness, m.mass, 3);
  EXPECT_EQ(classify_blade_mode(blade, modes.shapes.col(0)).label(), "1B");
  EXPECT_EQ(classify_blade_mode(blade, modes.shapes.col(1)).label(), "2B");
  EXPECT_EQ(classify_blade_mode(blade, modes.shapes.col(2)).label(), "1T");
}

TEST(BladeGenerator, RejectsBadGeometry) {
  BladeGeometry g;
  g.tip_radius = g.hub_radius;
  EXPECT_THROW(generate_blade(g), std::invalid_argument);
  g = BladeGeometry{};
  g.thickness_elements = 3;
  EXPECT_THROW(generate_blade(g), std::invalid_argument);
  EXPECT_THROW(generate_blade(BladeGeometry{}, 0), std::invalid_argument);
}

}  // namespace

}  // namespace hbtrack_tests::file_blade_model
