// Case files with very long lines (issue 39): toml11 costs each value the length of its line, so
// the reader breaks long lines after their arrays' commas before parsing; the values read are the
// same and every message names the line of the file as written.
#include <gtest/gtest.h>

#include <ctime>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "hbtrack/io/case_file.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_long_toml_lines {

namespace fs = std::filesystem;
using hbtrack::CaseError;
using hbtrack::load_case;

namespace {

fs::path write_case(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_long_toml_lines_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

std::string error_of(const fs::path& path) {
  try {
    load_case(path.string());
  } catch (const CaseError& e) {
    return e.what();
  }
  return "(no error)";
}

// "[a, b, ...]" of n items on one line; item(i) gives each.
template <class Item>
std::string one_line_array(int n, Item item) {
  std::string text = "[";
  for (int i = 0; i < n; ++i) text += (i ? ", " : "") + item(i);
  return text + "]";
}

// A 1000-dof model whose names, mass and stiffness are each one line of 5 to 8 KB (above the
// 4 KiB from which lines are broken), the last two arrays inside inline tables; `line13` is
// line 13 (harmonic_balance's harmonics).
std::string thousand_dof_case(const std::string& line11 = "amplitude = 1.0", const std::string& line13 = "harmonics = 3",
                              const std::string& last_mass = "1.0") {
  constexpr int n = 1000;
  const auto name = [](int i) { return "\"n" + std::to_string(i) + "\""; };
  const std::string mass = one_line_array(n, [&](int i) { return i == n - 1 ? last_mass : std::string("1.0"); });
  return "[model]\ndofs = " + one_line_array(n, name) + "\nM = { diagonal = " + mass +
         " }\nK = { diagonal = " + one_line_array(n, [](int i) { return std::to_string(2.0 + i); }) +
         " }\n[damping]\nrayleigh = [0.0, 0.01]\n[[forcing]]\ndof = \"n0\"\ncos = 0.1\n[parameters]\n" + line11 + "\n[harmonic_balance]\n" +
         line13 + "\n[continuation]\nomega_start = 0.5\nomega_end = 1.5\n[[outputs]]\nname = \"n0\"\ndof = \"n0\"\n";
}

}  // namespace

TEST(LongTomlLines, ValuesReadFromLongLinesAreTheValuesWritten) {
  const hbtrack::CaseDefinition c = load_case(write_case("thousand.toml", thousand_dof_case()).string());
  ASSERT_EQ(c.model.dofs(), 1000);
  EXPECT_EQ(c.model.dof_names.front(), "n0");
  EXPECT_EQ(c.model.dof_names.back(), "n999");
  EXPECT_EQ(c.model.mass(999, 999), 1.0);
  EXPECT_EQ(c.model.stiffness(999, 999), 1001.0);
  EXPECT_EQ(c.model.stiffness(0, 1), 0.0);
}

TEST(LongTomlLines, MessagesNameTheLinesOfTheFileAsWritten) {
  // After the long lines: a value's line, and a syntax error's.
  EXPECT_NE(error_of(write_case("after.toml", thousand_dof_case("amplitude = 1.0", "harmonics = \"three\"")))
                .find("after.toml:13: harmonic_balance.harmonics: expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of(write_case("syntax.toml", thousand_dof_case("amplitude = = 1.0"))).find("syntax.toml:11: TOML syntax error"),
            std::string::npos);
  // On a long line, after the breaks made in it: still its own line.
  const std::string inside = error_of(write_case("inside.toml", thousand_dof_case("amplitude = 1.0", "harmonics = 3", "\"x\"")));
  EXPECT_NE(inside.find("inside.toml:3: model.M.diagonal"), std::string::npos) << inside;
}

// The input: 20 000 node names and five lists of 20 000 values, each on one line, took
// 10 s of CPU in toml11 (one value per line: 0.25 s). The template then fails on its dof. The
// bound is on this process's CPU time (other processes on the cores do not inflate it), 10 s:
// the quadratic parse's own time, 40 times the linear one's, which leaves the sanitizers' slowdown.
TEST(LongTomlLines, TwentyThousandValuesOnOneLineParseInLinearTime) {
  constexpr int kNodes = 20000;
  const std::string nodes = one_line_array(kNodes, [](int i) { return "\"n" + std::to_string(i) + "\""; });
  const std::string list = one_line_array(kNodes, [](int i) { return std::to_string(0.1 + i * 1e-6); });
  std::string text =
      "[model]\ndofs = [\"x\"]\nM = [[1.0]]\nK = [[1.0]]\n[[elements]]\ntype = \"cubic_spring\"\ndofs = [\"d{node}\"]\nnodes = " + nodes +
      "\n";
  for (const char* key : {"cubic_stiffness", "a", "b", "c", "d"}) text += std::string(key) + ".per_node = " + list + "\n";
  const fs::path path = write_case("templates_one_line.toml", text);
  const std::clock_t t0 = std::clock();
  const std::string error = error_of(path);
  EXPECT_LT(static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC, 10.0);
  EXPECT_NE(error.find("elements[0]"), std::string::npos) << error;
}

}  // namespace hbtrack_tests::file_long_toml_lines
