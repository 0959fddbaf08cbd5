// Names that head CSV columns and numbers given as flags are checked before anything is written
// (issue 39): a dof name with a comma made a states.csv nothing could read back, and
// `--mode 4294967297` computed mode 1.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_input_names_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::run_cli;

namespace {

fs::path temp_dir() {
  static const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_input_names", true);
  return dir;
}

// A two-dof linear case with these (TOML) dof names.
fs::path two_dof_case(const std::string& name, const std::string& dofs_value) {
  const fs::path path = temp_dir() / (name + ".toml");
  std::ofstream(path) << "[model]\ndofs = " << dofs_value
                      << "\nM = [[1.0, 0.0], [0.0, 1.0]]\nK = [[2.0, -1.0], [-1.0, 2.0]]\n"
                         "[damping]\nC = [[0.02, 0.0], [0.0, 0.02]]\n[continuation]\nomega_start = 0.5\nomega_end = 2.0\n";
  return path;
}

void expect_bad_input(const CliRun& r, const fs::path& out, const std::string& words) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace

TEST(InputNames, DofNamesThatWouldBreakACsvHeaderAreRefused) {
  const fs::path out = temp_dir() / "out";
  ASSERT_EQ(run_cli("frc " + two_dof_case("fine", "[\"a\", \"b\"]").string() + " -q -o " + out.string()).exit_code, 0);
  fs::remove_all(out);
  const std::vector<std::pair<std::string, std::string>> bad{{"comma", "[\"a,b\", \"c\"]"},     {"newline", "[\"a\\nb\", \"c\"]"},
                                                             {"quote", "[\"a\\\"b\", \"c\"]"},  {"tab", "[\"a\\tb\", \"c\"]"},
                                                             {"nul", "[\"a\\u0000b\", \"c\"]"}, {"empty", "[\"\", \"c\"]"}};
  for (const auto& [name, dofs] : bad) {
    const CliRun r = run_cli("frc " + two_dof_case(name, dofs).string() + " -q -o " + out.string());
    SCOPED_TRACE(name);
    expect_bad_input(r, out, "model.dofs");
  }
}

TEST(InputNames, ParameterNamesThatWouldBreakACsvHeaderAreRefused) {
  const fs::path out = temp_dir() / "param_out";
  const fs::path path = temp_dir() / "param.toml";
  std::ofstream(path)
      << "[model]\ndofs = [\"x\"]\nM = [[1.0]]\nK = [[1.0]]\n[parameters]\n\"k,2\" = 1.0\n[continuation]\nomega_start = 0.5\nomega_end = "
         "1.5\n";
  expect_bad_input(run_cli("frc " + path.string() + " -q -o " + out.string()), out, "parameter name 'k,2' holds a comma");
}

// A name an element, a forcing or an output refers to is quoted in the reason: a newline or tab
// in it split the one-line reason in two ("unknown dof 'a", "b'"; issue 39's hostile rerun).
TEST(InputNames, AControlCharacterInAQuotedNameStaysOnOneLine) {
  const fs::path out = temp_dir() / "quoted_out";
  const fs::path path = temp_dir() / "quoted.toml";
  std::ofstream(path) << "[model]\ndofs = [\"a\", \"b\"]\nM = [[1.0, 0.0], [0.0, 1.0]]\nK = [[2.0, -1.0], [-1.0, 2.0]]\n"
                         "[[elements]]\ntype = \"cubic_spring\"\ndofs = [\"a\\nb\\t\\u0001\"]\ncubic_stiffness = 0.1\n"
                         "[continuation]\nomega_start = 0.5\nomega_end = 2.0\n";
  expect_bad_input(run_cli("frc " + path.string() + " -q -o " + out.string()), out, "unknown dof 'a\\nb\\t\\x01'");
}

// A names file saved by a Windows editor starts with a byte-order mark, which became part of
// the first name ("unknown dof" for an output naming it).
TEST(InputNames, AByteOrderMarkIsNotPartOfTheFirstName) {
  const fs::path names = temp_dir() / "names.txt", out = temp_dir() / "bom_out";
  std::ofstream(names) << "\xEF\xBB\xBF"
                       << "a\nb\n";
  const fs::path path = temp_dir() / "bom.toml";
  std::ofstream(path) << "[model]\ndofs = { file = \"names.txt\" }\nM = [[1.0, 0.0], [0.0, 1.0]]\nK = [[2.0, -1.0], [-1.0, 2.0]]\n"
                         "[damping]\nC = [[0.02, 0.0], [0.0, 0.02]]\n[[forcing]]\ndof = \"a\"\nharmonic = 1\ncos = "
                         "1.0\n[continuation]\nomega_start = 0.5\nomega_end = 2.0\n";
  const CliRun r = run_cli("frc " + path.string() + " -q -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// parse_integer's value went through static_cast<int>: 2^32 + 1 became 1.
TEST(InputNames, IntegerFlagsBeyondAnIntAreRefused) {
  const fs::path out = temp_dir() / "mode_out";
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  expect_bad_input(run_cli("backbone " + duffing + " --mode 4294967297 --range 0.01:2 -q -o " + out.string()), out,
                   "--mode: must be at most 2147483647");
}

// backbone's own refusals came after its folder existed: exit 3, the folder left `running`.
TEST(InputNames, BackbonesBadInputIsExit2BeforeAnyFolder) {
  const fs::path out = temp_dir() / "backbone_out";
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  expect_bad_input(run_cli("backbone " + duffing + " --set harmonic_balance.subharmonic=2 --range 0.01:2 -q -o " + out.string()), out,
                   "subharmonic = 1");
  const fs::path rigid = temp_dir() / "rigid.toml";
  std::ofstream(rigid) << "[model]\ndofs = [\"a\", \"b\"]\nM = [[1.0, 0.0], [0.0, 1.0]]\nK = [[1.0, -1.0], [-1.0, 1.0]]\n"
                          "[[elements]]\ntype = \"cubic_spring\"\ndofs = [\"a\"]\ncubic_stiffness = 0.1\n[continuation]\nomega_start = "
                          "0.5\nomega_end = 2.0\n";
  expect_bad_input(run_cli("backbone " + rigid.string() + " --mode 1 --range 0.01:2 -q -o " + out.string()), out, "rigid-body mode");
  const std::string dlft = hbtrack::test::source_path("examples/frictional_contact_dlft.toml");
  expect_bad_input(run_cli("backbone " + dlft + " --range 0.01:2 -q -o " + out.string()), out, "with law = \"dlft\"");
}

}  // namespace hbtrack_tests::file_input_names_cli
