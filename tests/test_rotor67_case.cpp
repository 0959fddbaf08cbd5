// The shipped rotor 67 case against its geometry: friction at every tip node opposes the blade's
// motion, in the sense of rotation read from NASA's sections (the leading edge leads), and the
// same for the parametric blade's case. Reversing engine_order in a case fails these tests.
#include <gtest/gtest.h>

#include "hbtrack/io/blade_sections_reader.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/section_blade.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_rotor67_case {

namespace {

using namespace hbtrack;

// The circumferential friction force the casing applies to the blade at one tip node, in
// contact (1 um into the casing) and without vibration: its sign must be opposite to the
// blade's circumferential velocity, `sense` * rho * omega.
void expect_friction_opposes_the_motion(const std::string& case_path, int sense) {
  const CaseDefinition c = load_case(test::source_path(case_path));
  int tip_contacts = 0;
  for (const auto& element : c.elements) {
    if (element->type() != "tip_contact") continue;
    ++tip_contacts;
    const std::vector<double> p = element->property_values(c.parameters);
    const auto& names = element->property_names();
    const auto clearance = static_cast<size_t>(std::find(names.begin(), names.end(), "clearance") - names.begin());
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(1, 3), v = Eigen::MatrixXd::Zero(1, 3);
    x(0, 0) = p[clearance] + 1e-6;
    ElementResponse out;
    element->evaluate(x, v, 2000.0, p, out, false);
    ASSERT_GT(out.force(0, 0), 0.0) << case_path << ": the node should be in contact";
    // The element's force is the internal one (left-hand side); the casing acts with -force.
    const double on_the_blade = -out.force(0, 1);
    EXPECT_LT(on_the_blade * sense, 0.0) << case_path << ": friction pushes the blade along its own motion";
  }
  EXPECT_EQ(tip_contacts, 9) << case_path;
}

TEST(Rotor67Case, FrictionOpposesTheBladeMotionReadFromTheGeometry) {
  const BladeSections sections = read_blade_sections(test::source_path("data/rotor67/sections.csv"));
  const SectionBlade blade = generate_section_blade(sections, SectionBladeOptions{});
  ASSERT_EQ(blade.rotation.sense, blade_rotation_sense(blade));  // the table and the mesh agree
  expect_friction_opposes_the_motion("examples/rotor67/nominal.toml", blade.rotation.sense);
}

TEST(BladeCase, FrictionOpposesTheBladeMotionReadFromTheGeometry) {
  expect_friction_opposes_the_motion("examples/blade/nominal.toml", blade_rotation_sense(generate_blade(BladeGeometry{})));
}

}  // namespace

}  // namespace hbtrack_tests::file_rotor67_case
