// The element catalogue (elements/element_catalog.hpp): every variant of every type builds, its
// property specs name the element's properties in their order, and the case reader takes type
// names, keys, defaults and ranges from it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "hbtrack/elements/element_catalog.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_element_catalog {

namespace {

namespace fs = std::filesystem;
using hbtrack::ElementKey;
using hbtrack::ElementSetup;
using hbtrack::ElementType;
using hbtrack::PropertyRange;
using hbtrack::PropertySpec;

bool has_property_rows(const ElementType& type) {
  for (const ElementKey& key : type.keys)
    if (key.kind == ElementKey::Kind::property_rows) return true;
  return false;
}

// A case of three dofs with one element of `type` in the variant `setup`: its choices written
// out, `properties` as given (name = value text), on as many dofs as the type takes.
std::string write_case(const ElementType& type, const ElementSetup& setup,
                       const std::vector<std::pair<std::string, std::string>>& properties) {
  std::string text =
      "[model]\ndofs = [\"a\", \"b\", \"c\"]\nM = {diagonal = [1.0, 1.0, 1.0]}\n"
      "K = [[2.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, 1.0]]\n[[forcing]]\ndof = \"a\"\ncos = 0.1\n";
  text += "[[elements]]\ntype = \"" + type.type + "\"\n";
  text += type.dof_names.size() == 3                           ? "dofs = [\"a\", \"b\", \"c\"]\n"
          : type.dof_names.size() == 2 || type.directions == 2 ? "dofs = [\"a\", \"b\"]\n"
                                                               : "dofs = [\"a\"]\n";
  for (const auto& [key, value] : setup.choices) text += key + " = \"" + value + "\"\n";
  for (const auto& [name, value] : properties) text += name + " = " + value + "\n";
  text += "[continuation]\nomega_start = 0.5\nomega_end = 1.5\n[stability]\nmethod = \"none\"\n";
  std::string file = "hbtrack_catalog_" + type.type;
  for (const auto& [key, value] : setup.choices) file += "_" + value;
  const fs::path path = fs::temp_directory_path() / (file + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

// A value outside `range` (none exists for `any`).
double outside(PropertyRange range) { return range == PropertyRange::nonzero ? 0.0 : -1.0; }

}  // namespace

TEST(ElementCatalog, EveryVariantBuildsWithItsPropertiesInTheElementsOrder) {
  std::set<std::string> names;
  for (const ElementType& type : hbtrack::element_catalog()) {
    EXPECT_TRUE(names.insert(type.type).second) << type.type << " twice";
    EXPECT_EQ(hbtrack::find_element_type(type.type), &type);
    EXPECT_FALSE(type.summary.empty()) << type.type;
    const auto variants = hbtrack::element_variants(type);
    ASSERT_FALSE(variants.empty()) << type.type;
    for (const ElementSetup& setup : variants) {
      const hbtrack::ElementBuild built = type.build(setup);
      ASSERT_TRUE(built.element) << type.type;
      EXPECT_EQ(built.element->type(), type.type);
      std::vector<std::string> specs;
      for (const PropertySpec& p : built.properties) {
        specs.push_back(p.name);
        EXPECT_FALSE(p.unit.empty()) << type.type << "." << p.name << ": no unit";
        EXPECT_FALSE(p.doc.empty()) << type.type << "." << p.name << ": no doc";
        if (p.fallback) {
          EXPECT_TRUE(hbtrack::admits(p.range, *p.fallback)) << type.type << "." << p.name << ": default out of range";
        }
      }
      // Property rows (polynomial coefficients) follow the element's own layout instead.
      if (!has_property_rows(type)) {
        EXPECT_EQ(specs, built.element->property_names()) << type.type;
      }
    }
    for (const ElementKey& key : type.keys) EXPECT_FALSE(key.doc.empty()) << type.type << "." << key.name << ": no doc";
  }
  EXPECT_EQ(hbtrack::find_element_type("no_such_element"), nullptr);
}

TEST(ElementCatalog, AChoiceTheElementCannotTakeIsAnErrorOfItsKey) {
  const ElementType* tip = hbtrack::find_element_type("tip_contact");
  ASSERT_NE(tip, nullptr);
  ElementSetup setup = hbtrack::element_variants(*tip).front();
  setup.choices["friction"] = "sticky";
  try {
    tip->build(setup);
    FAIL() << "built with friction = sticky";
  } catch (const hbtrack::ElementKeyError& e) {
    EXPECT_EQ(e.key(), "friction");
  }
}

TEST(ElementCatalog, TheCaseReaderAcceptsExactlyTheTypesOfTheCatalogue) {
  // The reader lists the types it accepts when none is near the one asked for.
  try {
    hbtrack::load_case(hbtrack::test::source_path("examples/duffing.toml"), {"elements[0].type=\"qqqqqqqqqqqqqqqq\""});
    FAIL() << "an unknown element type was accepted";
  } catch (const hbtrack::CaseError& e) {
    const std::string message = e.what();
    const std::string marker = "expected one of: ";
    const size_t at = message.find(marker);
    ASSERT_NE(at, std::string::npos) << message;
    const std::string list = message.substr(at + marker.size(), message.find(')', at) - at - marker.size());
    std::set<std::string> accepted, catalogued;
    for (size_t start = 0; start < list.size();) {
      const size_t end = std::min(list.find(',', start), list.size());
      std::string type = list.substr(start, end - start);
      accepted.insert(type.erase(0, type.find_first_not_of(' ')));
      start = end + 1;
    }
    for (const ElementType& type : hbtrack::element_catalog()) catalogued.insert(type.type);
    EXPECT_EQ(accepted, catalogued) << message;
  }
}

TEST(ElementCatalog, TheReaderFillsDefaultsAndChecksRangesFromTheSpecs) {
  for (const ElementType& type : hbtrack::element_catalog()) {
    if (has_property_rows(type)) continue;  // polynomial_stiffness: no named properties
    for (const ElementSetup& setup : hbtrack::element_variants(type)) {
      const std::vector<PropertySpec> specs = type.build(setup).properties;
      // 1 is inside every range; the properties with a default are left out.
      std::vector<std::pair<std::string, std::string>> required;
      for (const PropertySpec& p : specs) {
        ASSERT_TRUE(hbtrack::admits(p.range, 1.0)) << type.type << "." << p.name;
        if (!p.fallback) required.emplace_back(p.name, "1.0");
      }
      const hbtrack::CaseDefinition c = hbtrack::load_case(write_case(type, setup, required));
      ASSERT_EQ(c.elements.size(), 1u);
      const std::vector<double> values = c.elements[0]->property_values(c.parameters);
      ASSERT_EQ(values.size(), specs.size()) << type.type;
      for (size_t p = 0; p < specs.size(); ++p) EXPECT_EQ(values[p], specs[p].fallback.value_or(1.0)) << type.type << "." << specs[p].name;
      // Each range is checked, with the spec's rule in the message.
      for (const PropertySpec& p : specs) {
        if (p.range == PropertyRange::any) continue;
        auto properties = required;
        properties.emplace_back(p.name, std::to_string(outside(p.range)));
        std::erase_if(properties, [&](const auto& kv) { return kv.first == p.name && kv.second == "1.0"; });
        try {
          hbtrack::load_case(write_case(type, setup, properties));
          ADD_FAILURE() << type.type << "." << p.name << " = " << outside(p.range) << " was accepted";
        } catch (const hbtrack::CaseError& e) {
          const std::string rule = p.range == PropertyRange::nonzero ? "must be nonzero" : "must be " + hbtrack::to_string(p.range);
          EXPECT_NE(std::string(e.what()).find("." + p.name + ": " + rule), std::string::npos) << e.what();
        }
      }
    }
  }
}

}  // namespace hbtrack_tests::file_element_catalog
