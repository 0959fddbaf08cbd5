// docs/case-file.md's element table is the element catalogue: every type, and for each its keys
// and properties with their units, defaults and ranges, so neither can drift.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "hbtrack/elements/element_catalog.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_element_catalog_docs {

namespace {

// One `name` [unit] (part; part; ...) of the element table's keys column.
struct DocumentedKey {
  std::string name, unit;
  std::vector<std::string> parts;
};

// Element type -> its documented keys, from the table under `[[elements]]`.
std::map<std::string, std::vector<DocumentedKey>> documented_elements() {
  std::ifstream in(hbtrack::test::source_path("docs/case-file.md"));
  std::map<std::string, std::vector<DocumentedKey>> out;
  std::string line;
  bool in_section = false;
  const std::regex row(R"(^\| `([a-z0-9_]+)` \|[^|]*\| (.*?) \|)");
  const std::regex entry(R"(`([A-Za-z_]+)`(?: \[([^\]]*)\])?(?: \(([^)]*)\))?)");
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) in_section = line.find("`[[elements]]`") != std::string::npos;
    std::smatch m;
    if (!in_section || !std::regex_search(line, m, row)) continue;
    const std::string cell = m[2];
    auto& keys = out[m[1]];
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), entry); it != std::sregex_iterator(); ++it) {
      DocumentedKey k{(*it)[1], (*it)[2], {}};
      std::stringstream parts((*it)[3].str());
      for (std::string part; std::getline(parts, part, ';');) k.parts.push_back(part.substr(part.find_first_not_of(' ')));
      keys.push_back(k);
    }
  }
  return out;
}

bool is_number(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

// The range a documented part states ("> 0", "!= 0 with sliding friction", ...), "" when none.
std::string stated_range(const std::string& part) {
  for (const char* r : {">= 0", ">= 1", "> -1", "> 0", "!= 0"})
    if (part.rfind(r, 0) == 0) return r;
  return "";
}

}  // namespace

TEST(ElementCatalogDocs, TheElementTableIsTheElementCatalogue) {
  const auto documented = documented_elements();
  std::set<std::string> types;
  for (const hbtrack::ElementType& type : hbtrack::element_catalog()) {
    types.insert(type.type);
    ASSERT_TRUE(documented.count(type.type)) << "docs/case-file.md: no row for element type " << type.type;
    // Every property of every variant, and every key that decides how the element is built.
    std::map<std::string, std::vector<hbtrack::PropertySpec>> properties;
    for (const hbtrack::ElementSetup& setup : hbtrack::element_variants(type))
      for (const hbtrack::PropertySpec& p : type.build(setup).properties) properties[p.name].push_back(p);
    std::set<std::string> expected, listed;
    for (const auto& [name, specs] : properties) expected.insert(name);
    for (const hbtrack::ElementKey& key : type.keys) expected.insert(key.name);
    for (const DocumentedKey& k : documented.at(type.type)) {
      listed.insert(k.name);
      double value = 0;
      const bool has_default = !k.parts.empty() && is_number(k.parts.front(), value);
      if (!properties.count(k.name)) {  // a key: its default as the case file writes it
        for (const hbtrack::ElementKey& key : type.keys)
          if (key.name == k.name && !key.fallback.empty()) {
            ASSERT_FALSE(k.parts.empty()) << type.type << "." << k.name << ": default " << key.fallback << " not documented";
            const std::string& first = k.parts.front();
            EXPECT_TRUE(first == key.fallback || first == "\"" + key.fallback + "\"") << type.type << "." << k.name << ": " << first;
          }
        continue;
      }
      std::set<std::string> ranges;
      for (const hbtrack::PropertySpec& p : properties.at(k.name)) {
        EXPECT_EQ(k.unit, p.unit) << type.type << "." << k.name;
        EXPECT_EQ(has_default, p.fallback.has_value())
            << type.type << "." << k.name << ": a default documented for a required property, or none for an optional one";
        if (has_default && p.fallback) {
          EXPECT_EQ(value, *p.fallback) << type.type << "." << k.name;
        }
        if (p.range != hbtrack::PropertyRange::any) ranges.insert(hbtrack::to_string(p.range));
      }
      std::set<std::string> stated;
      for (const std::string& part : k.parts)
        if (!stated_range(part).empty()) stated.insert(stated_range(part));
      EXPECT_EQ(stated, ranges) << type.type << "." << k.name << ": documented ranges";
    }
    EXPECT_EQ(listed, expected) << "docs/case-file.md: the keys of " << type.type;
  }
  std::set<std::string> documented_types;
  for (const auto& [type, keys] : documented) documented_types.insert(type);
  EXPECT_EQ(documented_types, types) << "docs/case-file.md: element types not in the catalogue";
}

}  // namespace hbtrack_tests::file_element_catalog_docs
