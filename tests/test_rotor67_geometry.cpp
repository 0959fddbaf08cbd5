// NASA rotor 67 from its published sections: the derived table, the shape the mesher builds from
// it (through every published point), the sense of rotation read from the geometry, and the
// generated mesh's tip nodes.
#include <gtest/gtest.h>

#include <cmath>

#include "hbtrack/io/blade_sections_reader.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/section_blade.hpp"
#include "hbtrack/util/cubic_spline.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_rotor67_geometry {

namespace {

using namespace hbtrack;

const BladeSections& rotor67() {
  static const BladeSections sections = read_blade_sections(test::source_path("data/rotor67/sections.csv"));
  return sections;
}

TEST(CubicSpline, PassesThroughItsKnotsAndIsExactOnCubicsWithLinearEnds) {
  Eigen::VectorXd t(5);
  t << 0.0, 0.3, 1.0, 1.2, 2.0;
  Eigen::MatrixXd y(5, 2);
  for (int i = 0; i < 5; ++i) y.row(i) << std::sin(t(i)), 2.0 * t(i) - 1.0;
  const NaturalCubicSpline spline(t, y);
  for (int i = 0; i < 5; ++i) EXPECT_LT((spline(t(i)) - y.row(i)).norm(), 1e-15);
  // A straight line is a natural spline: reproduced everywhere to round-off.
  EXPECT_NEAR(spline(0.77)(1), 2.0 * 0.77 - 1.0, 1e-14);
  EXPECT_THROW(NaturalCubicSpline(Eigen::Vector2d(1.0, 1.0), Eigen::MatrixXd::Zero(2, 1)), std::invalid_argument);
}

TEST(Rotor67Sections, TheDerivedTableHoldsFourteenSurfacesOfSeventyPoints) {
  const BladeSections& s = rotor67();
  ASSERT_EQ(s.surfaces.size(), 14u);
  for (const auto& surface : s.surfaces) EXPECT_EQ(surface.size(), 70u);
  EXPECT_EQ(s.blade_count, 22);
  // The reference README's figures (m): hub leading edge radius 0.0956, casing trailing edge 0.2478.
  EXPECT_NEAR(s.surfaces.front().front().radius, 0.0956, 5e-5);
  EXPECT_NEAR(s.surfaces.back().back().radius, 0.2478, 5e-5);
}

TEST(Rotor67Sections, TheShapePassesThroughEveryPublishedPointBelowTheTip) {
  const BladeSections& s = rotor67();
  const SectionBladeShape shape(s, {0.0, 0.0});  // no clearance, no thickness floor
  double worst = 0;
  for (int k = 0; k < shape.surfaces(); ++k) {
    const auto& fractions = shape.point_fractions(k);
    for (size_t i = 0; i < s.surfaces[static_cast<size_t>(k)].size(); ++i) {
      const SectionPoint& p = s.surfaces[static_cast<size_t>(k)][i];
      const double u = fractions(static_cast<Eigen::Index>(i));
      const Eigen::Vector3d suction = cartesian_point(p.axial, p.radius, p.rtheta_suction / p.radius);
      const Eigen::Vector3d pressure = cartesian_point(p.axial, p.radius, (p.rtheta_suction - p.tangential_thickness) / p.radius);
      worst = std::max({worst, (shape.point(u, 0.0, k) - suction).norm(), (shape.point(u, 1.0, k) - pressure).norm()});
    }
  }
  // The issue asks 1e-6 m; a spline through its knots gives round-off.
  EXPECT_LT(worst, 1e-9);
}

TEST(Rotor67Sections, TheTipIsTheCasingLessTheRunningClearanceNormalToIt) {
  const BladeSections& s = rotor67();
  const double clearance = 0.024 * 0.0254;
  const SectionBladeShape shape(s, {clearance, 0.0});
  const int tip = shape.surfaces() - 1;
  const SectionBladeShape casing_shape(s, {0.0, 0.0});
  // Point by point (the offset changes the arc-length fractions a little, so compare knots).
  for (Eigen::Index i = 0; i < shape.point_fractions(tip).size(); i += 23) {
    const Eigen::Vector4d casing = casing_shape.camber(casing_shape.point_fractions(tip)(i), tip);
    const Eigen::Vector4d at_tip = shape.camber(shape.point_fractions(tip)(i), tip);
    // Normal to a cone of half-angle ~10 degrees: mostly radial, clearance long.
    EXPECT_NEAR(std::hypot(casing(0) - at_tip(0), casing(1) - at_tip(1)), clearance, 1e-12);
    EXPECT_GT(casing(1) - at_tip(1), 0.95 * clearance);
    EXPECT_NEAR(casing(2), at_tip(2), 1e-14);  // same angles
  }
}

TEST(Rotor67Sections, TheLeadingEdgeLeadsAndThePressureSurfaceFacesTheMotion) {
  const RotationSense r = rotation_sense(rotor67());
  // In NASA's angle the tip's leading edge sits 80 mm behind (-theta) its trailing edge: the
  // blade turns towards -theta.
  EXPECT_EQ(r.sense, -1);
  EXPECT_LT(r.leading_edge_lead, -0.07);
  // Mirrored (theta -> -theta, suction and pressure surfaces swap), the leading edge leads
  // towards +theta while the pressure surface still faces -theta: not a compressor blade.
  BladeSections mirrored = rotor67();
  for (auto& surface : mirrored.surfaces)
    for (auto& p : surface) p.rtheta_suction = -(p.rtheta_suction - p.tangential_thickness);
  EXPECT_THROW(rotation_sense(mirrored), std::invalid_argument);
}

TEST(Rotor67Mesh, NineTipNodesOnTheTipFromLeadingToTrailingEdge) {
  SectionBladeOptions options;
  options.rim_depth = 0.02;
  const SectionBlade blade = generate_section_blade(rotor67(), options);
  ASSERT_EQ(blade.tip_nodes.size(), 9u);
  EXPECT_EQ(blade.rotation.sense, -1);
  const auto& nodes = blade.grid.mesh().nodes;
  const Eigen::Vector3d le = nodes[static_cast<size_t>(blade.tip_nodes.front())], te = nodes[static_cast<size_t>(blade.tip_nodes.back())];
  // Chord about 91 mm; tip radii 0.2555 - 0.0006 (leading) and 0.2478 - 0.0006 (trailing edge).
  EXPECT_NEAR((te - le).norm(), 0.091, 0.002);
  EXPECT_NEAR(blade.tip_frames.front().radius, 0.2549, 2e-4);
  EXPECT_NEAR(blade.tip_frames.back().radius, 0.2472, 2e-4);
  // The mesh's own sense agrees with the table's: the leading edge is behind in +theta.
  EXPECT_LT((le - te).dot(blade.tip_frames[4].circumferential()), -0.07);
  // The rim's bottom face is clamped: every node there has no free dof.
  for (int i = 0; i <= 2 * blade.grid.cells(0); i += 2) EXPECT_LT(blade.dofs.dof(blade.grid.node_at(i, 0, 0), 0), 0);
  EXPECT_EQ(blade.rim_layers, 4);
}

TEST(Rotor67Mesh, BadSectionTablesGetOneLineErrorsNamingTheLineAndColumn) {
  const std::string dir = ::testing::TempDir();
  auto write = [&](const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
    return path;
  };
  const std::string header = "# blade_count = 22\nsurface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m\n";
  auto message = [&](const std::string& path) {
    try {
      read_blade_sections(path);
    } catch (const CaseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(write("neg.csv", header + "1,1,0,0.1,0,-0.001\n")), dir + "/neg.csv:3: tangential_thickness_m: must be >= 0");
  EXPECT_EQ(message(write("nan.csv", header + "1,1,0,nan,0,0\n")), dir + "/nan.csv:3: radius_m: 'nan' is not a finite number");
  EXPECT_EQ(message(write("order.csv", header + "2,1,0,0.1,0,0\n")),
            dir + "/order.csv:3: surface: surfaces must be numbered 1, 2, ... in order");
  EXPECT_EQ(message(write("count.csv", "surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m\n1,1,0,0.1,0,0\n")),
            dir + "/count.csv:2: blade_count: missing (a comment line '# blade_count = N')");
  EXPECT_EQ(message(dir), dir + ": not a regular file");
}

// The parametric blade too: its leading edge (upstream, at -Z) leads towards -theta, so the
// sense that its case must use for the sliding speed is -1, like rotor 67's.
TEST(BladeGenerator, ParametricBladeTurnsWithItsLeadingEdgeAhead) {
  BladeGeometry g;
  g.span_elements = 2;
  const BladeModel blade = generate_blade(g);
  const auto& nodes = blade.grid.mesh().nodes;
  const Eigen::Vector3d le = nodes[static_cast<size_t>(blade.tip_nodes.front())], te = nodes[static_cast<size_t>(blade.tip_nodes.back())];
  EXPECT_EQ(blade_rotation_sense(blade), -1);
  EXPECT_LT((le - te).dot(blade.tip_frames[4].circumferential()), 0.0);
}

}  // namespace

namespace {

// `reduce --axis`: the frame about any axis is the frame about X carried by the rotation that
// takes X to that axis (here X -> Y -> Z -> X, and an axis through another origin).
TEST(CylindricalFrame, AboutAnyAxisIsTheFrameAboutXRotated) {
  Eigen::Matrix3d turn;
  turn << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // X -> Y, Y -> Z, Z -> X
  const Eigen::Vector3d p(0.03, 0.24, -0.05), origin(1.0, -2.0, 0.5);
  const hbtrack::CylindricalFrame about_x = hbtrack::cylindrical_frame_about_x(p);
  const hbtrack::CylindricalFrame about_y = hbtrack::cylindrical_frame(origin + turn * p, origin, 3.0 * Eigen::Vector3d::UnitY());
  EXPECT_NEAR(about_y.radius, about_x.radius, 1e-15);
  EXPECT_LT((about_y.directions - turn * about_x.directions).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_THROW(hbtrack::cylindrical_frame(p, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(hbtrack::cylindrical_frame(Eigen::Vector3d(2, 0, 0), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()),
               std::invalid_argument);
}

}  // namespace

}  // namespace hbtrack_tests::file_rotor67_geometry
