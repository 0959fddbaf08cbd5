// Shorter models (issue "models without copy-paste"): `[model] dofs` as a count or a names file,
// and [[elements]] blocks with `nodes` expanded into one element per node. The rewritten
// examples load exactly as their nine-block versions (tests/data/pre_templates/).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "hbtrack/elements/tip_contact.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_case_templates {

using namespace hbtrack;
namespace fs = std::filesystem;

namespace {

// Four dofs, two per node (a, b); a template on both nodes, then a plain element.
const char* kTemplated = R"(
[model]
dofs = ["a_x", "a_y", "b_x", "b_y"]
M = { diagonal = [1.0, 1.0, 1.0, 1.0] }
K = { diagonal = [1.0, 2.0, 3.0, 4.0] }
[[forcing]]
dof = "a_x"
cos = 1.0
[parameters]
k = 0.5
[[elements]]
type = "cubic_spring"
nodes = ["a", "b"]
dofs = ["{node}_x", "{node}_y"]
cubic_stiffness.per_node = [2.0, "k"]
lanczos = 1
[[elements]]
type = "cubic_spring"
dofs = ["b_y"]
cubic_stiffness = 3.0
[continuation]
omega_start = 0.5
omega_end = 2.0
)";

fs::path templates_dir() { return fs::temp_directory_path() / ("hbtrack_template_tests_" + std::to_string(getpid())); }

fs::path write_file(const std::string& name, const std::string& text) {
  fs::create_directories(templates_dir());
  const fs::path p = templates_dir() / name;
  std::ofstream(p) << text;
  return p;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string case_error(const fs::path& p, const std::vector<std::string>& overrides = {}) {
  try {
    load_case(p.string(), overrides);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "no error";
}

// Same elements in the same order: type, dofs, variant, property bindings, Lanczos filter.
void expect_same_elements(const CaseDefinition& a, const CaseDefinition& b) {
  EXPECT_EQ(a.model.dof_names, b.model.dof_names);
  EXPECT_EQ(a.parameters.names(), b.parameters.names());
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (size_t i = 0; i < a.elements.size(); ++i) {
    const NonlinearElement& x = *a.elements[i];
    const NonlinearElement& y = *b.elements[i];
    SCOPED_TRACE("element " + std::to_string(i));
    EXPECT_EQ(x.type(), y.type());
    EXPECT_EQ(x.dofs, y.dofs);
    EXPECT_EQ(x.property_names(), y.property_names());
    ASSERT_EQ(x.properties.size(), y.properties.size());
    for (size_t p = 0; p < x.properties.size(); ++p) {
      EXPECT_EQ(x.properties[p].parameter, y.properties[p].parameter) << x.property_names()[p];
      EXPECT_EQ(x.properties[p].scale, y.properties[p].scale) << x.property_names()[p];
      EXPECT_EQ(x.properties[p].offset, y.properties[p].offset) << x.property_names()[p];
    }
    EXPECT_EQ(x.lanczos_exponent, y.lanczos_exponent);
    const auto* tx = dynamic_cast<const TipContact*>(&x);
    const auto* ty = dynamic_cast<const TipContact*>(&y);
    ASSERT_EQ(tx == nullptr, ty == nullptr);
    if (tx) {
      EXPECT_EQ(tx->law_kind(), ty->law_kind());
      EXPECT_EQ(tx->friction(), ty->friction());
    }
  }
}

}  // namespace

TEST(CaseTemplates, DofCountNamesTheDofsX1ToXN) {
  const std::string text = replaced(
      replaced(replaced(replaced(kTemplated, "dofs = [\"a_x\", \"a_y\", \"b_x\", \"b_y\"]", "dofs = 4"), "dof = \"a_x\"", "dof = \"x1\""),
               "nodes = [\"a\", \"b\"]\ndofs = [\"{node}_x\", \"{node}_y\"]", "nodes = [\"1\", \"3\"]\ndofs = [\"x{node}\"]"),
      "dofs = [\"b_y\"]", "dofs = [\"x4\"]");
  const CaseDefinition c = load_case(write_file("count.toml", text).string());
  EXPECT_EQ(c.model.dof_names, (std::vector<std::string>{"x1", "x2", "x3", "x4"}));
  ASSERT_EQ(c.elements.size(), 3u);
  EXPECT_EQ(c.elements[1]->dofs, std::vector<int>{2});
  // The count must match M and K, as a list of names must.
  EXPECT_NE(case_error(write_file("count5.toml", replaced(text, "dofs = 4", "dofs = 5")))
                .find("model.M: expected 5x5 (one row per dof), got 4x4"),
            std::string::npos);
}

TEST(CaseTemplates, DofNamesFromAFileSkipBlankLinesAndComments) {
  write_file("names.txt", "# the dofs of nodes a and b\na_x\n  a_y   # indented, with a comment\n\nb_x\r\nb_y\n");
  const std::string text = replaced(kTemplated, "dofs = [\"a_x\", \"a_y\", \"b_x\", \"b_y\"]", "dofs = { file = \"names.txt\" }");
  const CaseDefinition c = load_case(write_file("names.toml", text).string());
  EXPECT_EQ(c.model.dof_names, (std::vector<std::string>{"a_x", "a_y", "b_x", "b_y"}));
}

// `hbtrack reduce` lists the reduced dofs in summary.json: a case reads them from there.
TEST(CaseTemplates, DofNamesFromTheSummaryOfAReduction) {
  write_file("summary.json", R"({"sizes": {"reduced": 4}, "dof_names": ["a_x", "a_y", "b_x", "b_y"]})");
  const std::string text = replaced(kTemplated, "dofs = [\"a_x\", \"a_y\", \"b_x\", \"b_y\"]", "dofs = { file = \"summary.json\" }");
  EXPECT_EQ(load_case(write_file("summary.toml", text).string()).model.dof_names, (std::vector<std::string>{"a_x", "a_y", "b_x", "b_y"}));
}

TEST(CaseTemplates, NodesExpandOneElementPerNodeInOrder) {
  const CaseDefinition c = load_case(write_file("templated.toml", kTemplated).string());
  ASSERT_EQ(c.elements.size(), 3u);
  EXPECT_EQ(c.elements[0]->dofs, (std::vector<int>{0, 1}));  // a_x, a_y
  EXPECT_EQ(c.elements[1]->dofs, (std::vector<int>{2, 3}));  // b_x, b_y
  EXPECT_EQ(c.elements[2]->dofs, std::vector<int>{3});
  EXPECT_EQ(c.elements[0]->properties[0].parameter, -1);
  EXPECT_EQ(c.elements[0]->properties[0].offset, 2.0);
  EXPECT_EQ(c.elements[1]->properties[0].parameter, c.parameters.find("k"));
  EXPECT_EQ(c.elements[0]->lanczos_exponent, 1.0);
  EXPECT_EQ(c.elements[1]->lanczos_exponent, 1.0);
  EXPECT_EQ(c.elements[2]->lanczos_exponent, 0.0);
  // --set addresses the expanded list: elements[1] is node b's element, elements[2] the plain one.
  const CaseDefinition set =
      load_case(write_file("templated.toml", kTemplated).string(), {"elements[1].cubic_stiffness=7", "elements[2].lanczos=2"});
  EXPECT_EQ(set.elements[0]->property_values(set.parameters)[0], 2.0);
  EXPECT_EQ(set.elements[1]->property_values(set.parameters)[0], 7.0);
  EXPECT_EQ(set.elements[2]->lanczos_exponent, 2.0);
  EXPECT_NE(case_error(write_file("templated.toml", kTemplated), {"elements[3].lanczos=1"}).find("'elements' has 3 entries"),
            std::string::npos);
}

TEST(CaseTemplates, BadDofsAndTemplatesGiveOneLineErrorsNamingTheField) {
  const std::string names = "dofs = [\"a_x\", \"a_y\", \"b_x\", \"b_y\"]";
  const std::string nodes = "nodes = [\"a\", \"b\"]";
  struct Bad {
    const char* name;
    std::string text;
    const char* expected;
  };
  const std::vector<Bad> cases = {
      {"zero_count", replaced(kTemplated, names, "dofs = 0"), "model.dofs: must be in [1, 4000]"},
      {"fractional_count", replaced(kTemplated, names, "dofs = 2.5"), "model.dofs: expected an array of dof names, a dof count N"},
      {"names_file_missing", replaced(kTemplated, names, "dofs = { file = \"nope.txt\" }"), "model.dofs.file: "},
      {"names_file_key", replaced(kTemplated, names, "dofs = { path = \"names.txt\" }"), "model.dofs.path: unknown key"},
      {"names_file_blank", replaced(kTemplated, names, "dofs = { file = \"two_on_a_line.txt\" }"),
       "two_on_a_line.txt:2: 'a_y b_x' is not one name (one name per line"},
      {"names_file_empty", replaced(kTemplated, names, "dofs = { file = \"comments_only.txt\" }"), "model.dofs.file: names no dof"},
      {"names_file_twice", replaced(kTemplated, names, "dofs = { file = \"twice.txt\" }"), "model.dofs: dof name 'a_x' appears twice"},
      {"names_file_short", replaced(kTemplated, names, "dofs = { file = \"three.txt\" }"),
       "model.M: expected 3x3 (one row per dof), got 4x4"},
      {"json_without_names", replaced(kTemplated, names, "dofs = { file = \"other.json\" }"), "other.json: no \"dof_names\" array"},
      {"json_malformed", replaced(kTemplated, names, "dofs = { file = \"bad.json\" }"), "bad.json: not valid JSON"},
      {"json_not_strings", replaced(kTemplated, names, "dofs = { file = \"numbers.json\" }"), "numbers.json: dof_names[1] is not a string"},
      {"nodes_without_mark", replaced(kTemplated, "dofs = [\"{node}_x\", \"{node}_y\"]", "dofs = [\"a_x\", \"a_y\"]"),
       "elements[0].nodes: no name in dofs contains {node}"},
      {"empty_nodes", replaced(kTemplated, nodes, "nodes = []"), "elements[0].nodes: an empty list"},
      {"duplicate_nodes", replaced(kTemplated, nodes, "nodes = [\"a\", \"b\", \"a\"]"), "elements[0].nodes[2]: node 'a' appears twice"},
      {"number_node", replaced(kTemplated, nodes, "nodes = [\"a\", 2]"), "elements[0].nodes[1]: expected a string"},
      {"nodes_not_array", replaced(kTemplated, nodes, "nodes = \"a\""), "elements[0].nodes: expected an array of node names"},
      {"mark_without_nodes", replaced(kTemplated, nodes + "\n", ""), "elements[0].dofs[0]: {node} is replaced only in a template"},
      {"per_node_without_nodes", replaced(kTemplated, "cubic_stiffness = 3.0", "cubic_stiffness.per_node = [3.0]"),
       "elements[2].cubic_stiffness.per_node: needs nodes"},
      {"per_node_short", replaced(kTemplated, "[2.0, \"k\"]", "[2.0]"),
       "elements[0].cubic_stiffness.per_node: expected an array with one entry per node (2)"},
      {"per_node_extra_key",
       replaced(kTemplated, "cubic_stiffness.per_node = [2.0, \"k\"]", "cubic_stiffness = { per_node = [2.0, \"k\"], scale = 2 }"),
       "elements[0].cubic_stiffness: a per_node table takes no other key"},
      // Errors of an expanded element name its index in the expanded list.
      {"expanded_unknown_dof", replaced(kTemplated, nodes, "nodes = [\"a\", \"c\"]"), "elements[1].dofs[0]: unknown dof 'c_x'"},
      {"expanded_bad_property", replaced(kTemplated, "[2.0, \"k\"]", "[2.0, \"kk\"]"),
       "elements[1].cubic_stiffness: unknown parameter 'kk'"},
  };
  write_file("two_on_a_line.txt", "a_x\na_y b_x\nb_y\n");
  write_file("comments_only.txt", "# nothing\n\n   \n");
  write_file("twice.txt", "a_x\na_y\na_x\nb_y\n");
  write_file("three.txt", "a_x\na_y\nb_x\n");
  write_file("other.json", R"({"names": ["a_x"]})");
  write_file("bad.json", R"({"dof_names": ["a_x",)");
  write_file("numbers.json", R"({"dof_names": ["a_x", 2, "b_x", "b_y"]})");
  for (const Bad& bad : cases) {
    const fs::path p = write_file(std::string(bad.name) + ".toml", bad.text);
    const std::string msg = case_error(p);
    EXPECT_NE(msg.find(bad.expected), std::string::npos) << bad.name << ": got '" << msg << "'";
    EXPECT_EQ(msg.find('\n'), std::string::npos) << bad.name << ": not one line: " << msg;
    EXPECT_EQ(msg.rfind(p.string() + ":", 0), 0u) << bad.name << ": does not start with the file name: " << msg;
  }
  // A template's nodes cannot be set from the command line: it is already expanded there.
  EXPECT_NE(case_error(write_file("templated.toml", kTemplated), {"elements[0].nodes=[\"a\"]"})
                .find("elements[0].nodes: templates are expanded before --set"),
            std::string::npos);
}

// The blade and rotor 67 cases, rewritten with one templated block and their dofs read from the
// reduction's summary.json, load exactly as the nine blocks they replace did.
TEST(CaseTemplates, RewrittenExamplesLoadAsTheirNineBlocks) {
  const std::vector<std::pair<const char*, const char*>> examples = {
      {"examples/blade/nominal.toml", "blade_nominal.toml"},
      {"examples/blade/sweep.toml", "blade_sweep.toml"},
      {"examples/rotor67/nominal.toml", "rotor67_nominal.toml"},
  };
  for (const auto& [example, before] : examples) {
    SCOPED_TRACE(example);
    const CaseDefinition now = load_case(test::source_path(example));
    ASSERT_EQ(now.elements.size(), 9u);
    // The old text as it was in the examples (git show), its matrix paths made absolute.
    std::string text = read_text(test::source_path(std::string("tests/data/pre_templates/") + before));
    for (size_t at; (at = text.find("\"../../data/")) != std::string::npos;) text.replace(at, 12, "\"" + test::source_path("data/"));
    const CaseDefinition then = load_case(write_file(before, text).string());
    expect_same_elements(now, then);
    EXPECT_TRUE(now.model.mass == then.model.mass);
    EXPECT_TRUE(now.model.damping == then.model.damping);
    EXPECT_TRUE(now.model.forcing[0].cos_part == then.model.forcing[0].cos_part);
    // `--set elements[k]...` (scripts/run-main-job.sh, docs/rotor67.md) reaches tip node k + 1.
    const CaseDefinition set = load_case(test::source_path(example), {"elements[8].engine_order=1"});
    const int engine_order = 5;
    EXPECT_EQ(set.elements[8]->property_names()[engine_order], "engine_order");
    EXPECT_EQ(set.elements[8]->property_values(set.parameters)[engine_order], 1.0);
    EXPECT_EQ(set.elements[7]->property_values(set.parameters)[engine_order], -1.0);
    EXPECT_EQ(set.model.dof_names[static_cast<size_t>(set.elements[8]->dofs[0])], "n9_r");
  }
}

}  // namespace hbtrack_tests::file_case_templates
