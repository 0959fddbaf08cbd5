// Inputs that used to crash or exhaust memory (issue 24, "Reliability, round 2"): each test
// feeds the input that failed and expects a one-line error instead.
#include <gtest/gtest.h>

#include <ctime>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/io/input_file.hpp"
#include "hbtrack/io/mat_file.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_input_limits {

namespace fs = std::filesystem;
using hbtrack::CaseError;
using hbtrack::load_case;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_input_limits_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

fs::path write_file(const std::string& name, const std::string& bytes) {
  const fs::path path = scratch(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string file_text(const fs::path& path) {
  std::stringstream ss;
  ss << std::ifstream(path, std::ios::binary).rdbuf();
  return ss.str();
}

// The message of the CaseError `load` throws ("" when it throws none).
template <class F>
std::string case_error(F load) {
  try {
    load();
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

const std::string kDuffing = hbtrack::test::source_path("examples/duffing.toml");

}  // namespace

// The TOML parser recursed once per bracket: 8 KB of '[' overflowed the stack (exit 139).
TEST(InputLimits, DeeplyNestedArraysAreRefusedBeforeParsing) {
  const fs::path path = write_file("deep.toml", "x=" + std::string(8000, '['));
  const std::string error = case_error([&] { load_case(path.string()); });
  EXPECT_NE(error.find(path.string() + ":1: arrays or inline tables nested deeper than 64 levels"), std::string::npos) << error;
}

TEST(InputLimits, DeeplyNestedMatrixAndInlineTablesAreRefused) {
  std::string text = file_text(kDuffing);
  const fs::path arrays = write_file("deep_m.toml", text + "\n[extra]\nM = " + std::string(10000, '[') + "\n");
  EXPECT_NE(case_error([&] { load_case(arrays.string()); }).find("nested deeper than 64"), std::string::npos);
  std::string tables = "t = ";
  for (int i = 0; i < 5000; ++i) tables += "{a=";
  const fs::path inline_tables = write_file("deep_tables.toml", tables + "\n");
  EXPECT_NE(case_error([&] { load_case(inline_tables.string()); }).find("nested deeper than 64"), std::string::npos);
}

// The same through --set (20 000 brackets crashed it).
TEST(InputLimits, DeeplyNestedOverrideIsRefused) {
  const std::string error = case_error([&] { load_case(kDuffing, {"amplitude=" + std::string(20000, '[')}); });
  EXPECT_NE(error.find("--set amplitude:1: arrays or inline tables nested deeper than 64"), std::string::npos) << error;
}

// Nesting within the limit, and brackets inside strings and comments, are not counted.
TEST(InputLimits, BracketsInStringsAndCommentsAndModestNestingPass) {
  const std::string brackets(200, '[');
  const std::string text = "# " + brackets + "\na = \"" + brackets + "\"\nb = '" + brackets + "'\nc = \"\"\"\n" + brackets +
                           "\"\"\"\"\nd = '''" + brackets + "''''\ne = \"\\\"" + brackets + "\"\nf = " + std::string(60, '[') +
                           std::string(60, ']') + "\n";
  EXPECT_NO_THROW(hbtrack::check_toml_nesting(text, "strings.toml"));
  // A bracket after a string that closes with extra quotes counts again.
  EXPECT_THROW(hbtrack::check_toml_nesting("c = [\"\"\"x\"\"\"\"," + std::string(100, '[') + "\n", "quotes.toml"), CaseError);
}

// An endless stream (/dev/zero) was read until memory ran out; only regular files are inputs.
TEST(InputLimits, CasePathMustBeARegularFile) {
  const std::string error = case_error([] { load_case("/dev/zero"); });
  EXPECT_NE(error.find("/dev/zero: is not a regular file"), std::string::npos) << error;
  EXPECT_NE(case_error([] { load_case("/tmp"); }).find("is a directory"), std::string::npos);
}

TEST(InputLimits, OverrideIsOneValue) {
  // Text after the value was dropped: 'amplitude=1 # x' and a second key after a newline.
  EXPECT_NE(case_error([&] {
              load_case(kDuffing, {"amplitude=0.5\ncontinuation.step=9"});
            }).find("--set amplitude: the value must be on one line"),
            std::string::npos);
  EXPECT_NE(case_error([&] { load_case(kDuffing, {"amplitude=0.5 0.7"}); }).find("expected a number, got '0.5 0.7'"), std::string::npos);
  // A '#' comment after the value: 'amplitude=0.5 #0.7' set 0.5 and exit 0.
  for (const std::string set :
       {"amplitude=0.5 #0.7", "amplitude=0.5 #", "harmonic_balance.harmonics=5 # 7", "elements[0].stiffness=1 #x"}) {
    const std::string error = case_error([&] { load_case(kDuffing, {set}); });
    EXPECT_NE(error.find("is one value followed by a '#' comment"), std::string::npos) << set << ": " << error;
  }
  // A '#' inside a string is text, not a comment.
  EXPECT_NO_THROW(load_case(kDuffing, {"outputs[0].name=\"x#1\""}));
  // An unknown name lists each known parameter once.
  const std::string unknown = case_error([&] { load_case(kDuffing, {"zzzzzzzzzzzz=1"}); });
  EXPECT_NE(unknown.find("(known: amplitude)"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find("amplitude, amplitude"), std::string::npos) << unknown;
  EXPECT_NO_THROW(load_case(kDuffing, {"amplitude=0.5"}));
}

// Issue 24: engine_order = 0 was accepted (no rotation: the tip's sliding speed loses its sense).
TEST(InputLimits, EngineOrderMustBeNonzero) {
  const std::string blade = hbtrack::test::source_path("examples/blade/nominal.toml");
  const std::string error = case_error([&] { load_case(blade, {"elements[0].engine_order=0"}); });
  EXPECT_NE(error.find("elements[0].engine_order: must be nonzero"), std::string::npos) << error;
}

// A v4 sparse matrix gives its size in its last data row; libmatio allocated the column
// pointers from it (4 228 000 004 bytes for this 94-byte file).
TEST(InputLimits, V4SparseSizeRowIsBoundedBeforeMatio) {
  const auto v4_sparse = [](double rows, double columns) {
    std::string bytes;
    const std::int32_t header[] = {2, 3, 3, 0, 2};  // sparse doubles; 3 x 3 record; not complex; name "K\0"
    bytes.append(reinterpret_cast<const char*>(header), sizeof header);
    bytes.append("K\0", 2);
    const double data[] = {1, 2, rows, 1, 2, columns, 5, 6, 0};  // (i, j, value) rows, then (m, n, 0)
    bytes.append(reinterpret_cast<const char*>(data), sizeof data);
    return bytes;
  };
  const fs::path good = write_file("v4_sparse.mat", v4_sparse(2, 2));
  const Eigen::MatrixXd k = hbtrack::read_mat_variable(good.string(), "K");
  ASSERT_EQ(k.rows(), 2);
  ASSERT_EQ(k.cols(), 2);
  EXPECT_EQ(k(0, 0), 5);
  EXPECT_EQ(k(1, 1), 6);
  const fs::path bad = write_file("v4_sparse_huge.mat", v4_sparse(2, 1.057e9));
  try {
    hbtrack::read_mat_variable(bad.string(), "K");
    FAIL() << "a size row of 1.057e9 columns was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the v4 sparse record at byte 0 claims columns = 1057000000"), std::string::npos) << e.what();
  }
}

// On a full disk summary.json was renamed into place with 0 bytes: the stream reported the
// failed write only when it was closed. A file-size limit of 64 bytes (SIGXFSZ ignored, so the
// write fails with EFBIG as on a full disk) in a child process stands for the full disk.
TEST(InputLimits, AFailedResultWriteLeavesTheOldFileAndSaysWhy) {
  const fs::path path = scratch("summary.json");
  hbtrack::write_json_atomically(path.string(), {{"points", 5000}});
  const std::string before = file_text(path);
  nlohmann::json big;
  for (int i = 0; i < 100; ++i) big["key" + std::to_string(i)] = i;
  std::fflush(nullptr);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64, 64};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      hbtrack::write_json_atomically(path.string(), big);
    } catch (const std::runtime_error& e) {
      _exit(std::strstr(e.what(), "write failed: File too large") ? 0 : 2);
    }
    _exit(1);  // the failure went unseen
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no error reported; 2: another message";
  EXPECT_EQ(file_text(path), before);
  EXPECT_FALSE(fs::exists(path.string() + ".tmp"));
}

// Template expansion copied the whole block, every per_node list with it, once per node: 20 000
// nodes and 5 lists were still expanding after 400 s. Now linear: the case is read (and refused
// at its first element's unknown key) in 0.5 s (Release). The bound is on this process's CPU
// time, which other processes on the cores do not inflate (the wall time under the sanitizers
// on a loaded machine reached 10.5 s), and lies between the two: 60 s, under the quadratic
// expansion's 400 s by a factor 7 and over the sanitizers' slowdown of the linear one.
TEST(InputLimits, TemplateExpansionIsLinearInTheNodes) {
  constexpr int kNodes = 20000;
  std::string nodes, list;
  for (int i = 0; i < kNodes; ++i) {
    // One value per line: toml11 itself is quadratic in the length of a line.
    nodes += (i ? ",\n\"n" : "\"n") + std::to_string(i) + "\"";
    list += (i ? ",\n" : "") + std::to_string(0.1 + i * 1e-6);
  }
  std::string text =
      "[model]\ndofs = [\"x\"]\nM = [[1.0]]\nK = [[1.0]]\n[[elements]]\ntype = \"cubic_spring\"\ndofs = [\"d{node}\"]\nnodes = [" + nodes +
      "]\n";
  for (const char* key : {"cubic_stiffness", "a", "b", "c", "d"}) text += std::string(key) + ".per_node = [" + list + "]\n";
  const fs::path path = write_file("templates_20000.toml", text);
  const std::clock_t t0 = std::clock();
  const std::string error = case_error([&] { load_case(path.string()); });
  EXPECT_LT(static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC, 60.0);
  EXPECT_NE(error.find("elements[0]"), std::string::npos) << error;
}

}  // namespace hbtrack_tests::file_input_limits
