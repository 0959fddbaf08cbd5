// Every property of every element type (and variant) the case reader knows can be bound to a
// named parameter, so that it can be varied with --set and tracked (issue 19: "all bindable to
// named parameters"). The list of types is the reader's own: a type it accepts that this test
// does not cover fails it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "hbtrack/io/case_file.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_element_bindings {

using namespace hbtrack;
namespace fs = std::filesystem;

namespace {

struct Variant {
  const char* name;
  const char* type;
  const char* dofs;
  std::vector<std::pair<std::string, double>> properties;  // every bindable property, with a valid value
  const char* fixed_keys;                                  // non-bindable keys (variant, structure)
};

const std::vector<Variant>& variants() {
  static const std::vector<Variant> list{
      {"cubic_spring", "cubic_spring", "[\"a\"]", {{"cubic_stiffness", 0.5}}, ""},
      {"unilateral_spring", "unilateral_spring", "[\"a\"]", {{"stiffness", 5.0}, {"gap", 0.1}, {"width", 0.01}}, ""},
      {"regularized_contact", "regularized_contact", "[\"a\"]", {{"stiffness", 5.0}, {"gap", 0.1}, {"width", 0.01}}, ""},
      {"tanh_friction", "tanh_friction", "[\"a\"]", {{"mu", 0.3}, {"normal_load", 1.0}, {"regularization_velocity", 0.01}}, ""},
      {"tip_contact",
       "tip_contact",
       "[\"a\", \"b\", \"c\"]",
       {{"stiffness", 1.0},
        {"clearance", 0.1},
        {"width", 0.1},
        {"mu", 0.2},
        {"radius", 0.3},
        {"engine_order", 1.0},
        {"rotation_speed", 0.5}},
       ""},
      {"tip_contact_stick_slip",
       "tip_contact",
       "[\"a\", \"b\", \"c\"]",
       {{"stiffness", 1.0},
        {"clearance", 0.1},
        {"width", 0.1},
        {"mu", 0.2},
        {"radius", 0.3},
        {"engine_order", 1.0},
        {"rotation_speed", 0.5},
        {"tangential_stiffness", 5.0}},
       "friction = \"stick_slip\"\n"},
      {"polynomial_stiffness",
       "polynomial_stiffness",
       "[\"a\", \"b\"]",
       {{"coefficients[0][0]", 1.0}, {"coefficients[0][1]", 0.5}, {"coefficients[1][0]", -0.2}, {"coefficients[1][1]", 0.3}},
       "exponents = [[3, 0], [1, 2]]\n"},
      {"power_damper", "power_damper", "[\"a\"]", {{"coefficient", 0.1}, {"exponent", 2.0}}, ""},
      {"elastic_dry_friction", "elastic_dry_friction", "[\"a\"]", {{"stiffness", 20.0}, {"limit_force", 1.0}}, ""},
      {"elastic_dry_friction_2d", "elastic_dry_friction_2d", "[\"a\", \"b\"]", {{"stiffness", 20.0}, {"limit_force", 1.0}}, ""},
      {"iwan", "iwan", "[\"a\"]", {{"limit_force", 1.0}, {"stiffness", 3.0}, {"chi", -0.5}, {"beta", 0.1}}, ""},
      {"frictional_contact",
       "frictional_contact",
       "[\"a\", \"b\"]",
       {{"normal_stiffness", 10.0}, {"tangential_stiffness", 5.0}, {"mu", 0.3}, {"normal_preload", 0.05}},
       ""},
      {"frictional_contact_2d",
       "frictional_contact_2d",
       "[\"a\", \"b\", \"c\"]",
       {{"normal_stiffness", 10.0}, {"tangential_stiffness", 5.0}, {"mu", 0.3}, {"normal_preload", 0.05}},
       ""},
      {"frictional_contact_dlft",
       "frictional_contact",
       "[\"a\", \"b\"]",
       {{"mu", 0.3}, {"epsilon", 1.0}, {"gap", 0.01}},
       "law = \"dlft\"\n"},
  };
  return list;
}

// The parameter bound to property i of a variant.
std::string parameter(size_t i) { return "p" + std::to_string(i); }

fs::path write_case(const Variant& v) {
  std::string text =
      "[model]\ndofs = [\"a\", \"b\", \"c\"]\nM = {diagonal = [1.0, 1.0, 1.0]}\n"
      "K = [[2.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, 1.0]]\n[[forcing]]\ndof = \"a\"\ncos = 0.1\n[parameters]\n";
  for (size_t i = 0; i < v.properties.size(); ++i) text += parameter(i) + " = " + std::to_string(v.properties[i].second) + "\n";
  text += std::string("[[elements]]\ntype = \"") + v.type + "\"\ndofs = " + v.dofs + "\n" + v.fixed_keys;
  const std::string name = v.properties.front().first;
  if (name.rfind("coefficients", 0) == 0) {
    text += "coefficients = [[\"p0\", \"p1\"], [\"p2\", \"p3\"]]\n";
  } else {
    for (size_t i = 0; i < v.properties.size(); ++i) text += v.properties[i].first + " = \"" + parameter(i) + "\"\n";
  }
  text += "[continuation]\nomega_start = 0.5\nomega_end = 1.5\n[stability]\nmethod = \"none\"\n";
  const fs::path p = fs::temp_directory_path() / (std::string("hbtrack_binding_") + v.name + ".toml");
  std::ofstream(p) << text;
  return p;
}

}  // namespace

TEST(ElementBindings, EveryPropertyOfEveryElementFollowsItsNamedParameter) {
  for (const Variant& v : variants()) {
    const fs::path path = write_case(v);
    const CaseDefinition c = load_case(path.string());
    ASSERT_EQ(c.elements.size(), 1u) << v.name;
    const auto& element = *c.elements[0];
    ASSERT_EQ(element.property_names().size(), v.properties.size()) << v.name << ": a property the test does not bind";
    for (size_t i = 0; i < v.properties.size(); ++i) {
      EXPECT_EQ(element.property_names()[i], v.properties[i].first) << v.name;
      EXPECT_DOUBLE_EQ(element.property_values(c.parameters)[i], v.properties[i].second) << v.name << "." << v.properties[i].first;
      // --set on the parameter moves the property, and only it.
      const double moved = 1.25 * v.properties[i].second + (v.properties[i].second == 0.0 ? 0.5 : 0.0);
      const CaseDefinition set = load_case(path.string(), {parameter(i) + "=" + std::to_string(moved)});
      const std::vector<double> values = set.elements[0]->property_values(set.parameters);
      for (size_t j = 0; j < values.size(); ++j)
        EXPECT_DOUBLE_EQ(values[j], j == i ? moved : v.properties[j].second) << v.name << ": --set " << parameter(i) << ", property " << j;
    }
  }
}

TEST(ElementBindings, CoversEveryElementTypeTheReaderKnows) {
  // The reader lists its types when none is near the one asked for.
  const Variant unknown{"unknown", "zzzzzzzzzzzz", "[\"a\"]", {{"stiffness", 1.0}}, ""};
  try {
    load_case(write_case(unknown).string());
    FAIL() << "an unknown type was accepted";
  } catch (const CaseError& e) {
    const std::string msg = e.what();
    const size_t list = msg.find("expected one of: ");
    ASSERT_NE(list, std::string::npos) << msg;
    std::set<std::string> covered;
    for (const Variant& v : variants()) covered.insert(v.type);
    std::string rest = msg.substr(list + 17);
    rest = rest.substr(0, rest.find(')'));
    size_t count = 0;
    for (size_t start = 0; start < rest.size();) {
      const size_t end = std::min(rest.find(',', start), rest.size());
      std::string type = rest.substr(start, end - start);
      type.erase(0, type.find_first_not_of(' '));
      EXPECT_TRUE(covered.count(type)) << "element type '" << type << "' has no binding check";
      ++count;
      start = end + 1;
    }
    EXPECT_EQ(count, covered.size()) << msg;
  }
}

}  // namespace hbtrack_tests::file_element_bindings
