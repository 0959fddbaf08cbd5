// make-blade --geometry with bad section tables and flags (issue 39): each is one line and exit 2
// before any folder exists, never an abort, a silent default or minutes of meshing.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_blade_input_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::run_cli;

namespace {

fs::path temp_dir() {
  static const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_blade_input", true);
  return dir;
}

struct Row {
  std::vector<std::string> cells;
};

// Rotor 67's hub and casing sections, 8 points each: a valid blade meshed in a second.
std::vector<std::vector<Row>> two_surfaces() {
  std::ifstream in(hbtrack::test::source_path("data/rotor67/sections.csv"));
  std::vector<std::vector<Row>> surfaces(2);
  bool header = false;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    Row row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.cells.push_back(cell);
    const int surface = std::stoi(row.cells[0]), point = std::stoi(row.cells[1]);
    if ((surface == 1 || surface == 14) && (point == 1 || point % 10 == 0)) surfaces[surface == 1 ? 0 : 1].push_back(row);
  }
  return surfaces;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", v);
  return text;
}

// The table with `preamble` lines before the header, and `between` surfaces interpolated between
// the first two.
std::string sections_file(const std::string& name, const std::string& preamble, std::vector<std::vector<Row>> surfaces, int between = 0) {
  const fs::path path = temp_dir() / name;
  std::ofstream out(path);
  out << preamble << "surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m\n";
  const auto hub = surfaces[0], tip = surfaces[1];
  for (int k = 1; k <= between; ++k) {
    const double f = double(k) / (between + 1);
    std::vector<Row> surface = hub;
    for (size_t p = 0; p < surface.size(); ++p)
      for (int c = 2; c < 6; ++c) surface[p].cells[c] = number((1 - f) * std::stod(hub[p].cells[c]) + f * std::stod(tip[p].cells[c]));
    surfaces.insert(surfaces.end() - 1, surface);
  }
  for (size_t s = 0; s < surfaces.size(); ++s)
    for (size_t p = 0; p < surfaces[s].size(); ++p) {
      const auto& c = surfaces[s][p].cells;
      out << s + 1 << ',' << p + 1 << ',' << c[2] << ',' << c[3] << ',' << c[4] << ',' << c[5] << '\n';
    }
  return path.string();
}

CliRun make_blade(const std::string& geometry, const std::string& extra, const fs::path& out) {
  return run_cli("make-blade -q --geometry " + geometry + " " + extra + " -o " + out.string());
}

void expect_bad_input(const CliRun& r, const fs::path& out, const std::string& words) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out)) << "a folder was made for bad input";
}

}  // namespace

// A subnormal thickness at the leading edge (strtod's ERANGE) was "not a finite number".
TEST(BladeInput, TheTwoSurfaceTableIsABlade) {
  const fs::path out = temp_dir() / "good";
  auto surfaces = two_surfaces();
  for (auto& s : surfaces) s.front().cells[5] = "1e-310";
  const CliRun r = make_blade(sections_file("subnormal.csv", "# blade_count = 22\n", surfaces), "", out);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// Trailing edge first, or no thickness: the rotation-sense check threw while the blade was being
// built in one aggregate, which GCC 12 destroyed twice ("double free or corruption", exit 134).
TEST(BladeInput, PointsTrailingEdgeFirstOrNoThicknessAreBadInputNotAnAbort) {
  auto reversed = two_surfaces();
  for (auto& s : reversed) std::reverse(s.begin(), s.end());
  auto flat = two_surfaces();
  for (auto& s : flat)
    for (auto& p : s) p.cells[5] = "0";
  const fs::path out = temp_dir() / "reversed";
  expect_bad_input(make_blade(sections_file("reversed.csv", "# blade_count = 22\n", reversed), "", out), out,
                   "not the blade of a compressor rotor");
  expect_bad_input(make_blade(sections_file("flat.csv", "# blade_count = 22\n", flat), "", out), out,
                   "not the blade of a compressor rotor");
}

TEST(BladeInput, BladeCountIsBoundedAndGivenOnce) {
  const fs::path out = temp_dir() / "count";
  expect_bad_input(make_blade(sections_file("million.csv", "# blade_count = 1000000\n", two_surfaces()), "", out), out,
                   "blade_count: must be <= 1000");
  expect_bad_input(make_blade(sections_file("twice.csv", "# blade_count = 22\n# blade_count = 30\n", two_surfaces()), "", out), out,
                   "blade_count: given twice");
}

// 3000 surfaces meshed for minutes (the cross-surface spline is evaluated per node); the table is
// now refused at its 101st surface.
TEST(BladeInput, TooManyStreamSurfacesAreRefusedAtOnce) {
  const fs::path out = temp_dir() / "surfaces";
  const auto t0 = std::chrono::steady_clock::now();
  expect_bad_input(make_blade(sections_file("many.csv", "# blade_count = 22\n", two_surfaces(), 150), "", out), out,
                   "at most 100 stream surfaces");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  expect_bad_input(make_blade(sections_file("good.csv", "# blade_count = 22\n", two_surfaces()), "--refine 17", out), out,
                   "--refine: must be in 1..16");
}

// A negative or NaN depth meant "the default" (any value < 0 did).
TEST(BladeInput, RimDepthMustBeANonNegativeNumber) {
  const fs::path out = temp_dir() / "rim";
  const std::string table = sections_file("good.csv", "# blade_count = 22\n", two_surfaces());
  expect_bad_input(make_blade(table, "--rim-depth=-5", out), out, "--rim-depth: must be >= 0");
  expect_bad_input(make_blade(table, "--rim-depth nan", out), out, "--rim-depth: must be a finite number");
}

// SIGTERM was noted for a continuation make-blade never runs: the meshing went on for minutes.
TEST(BladeInput, SigtermEndsAMakeBladeAtOnce) {
  const fs::path out = temp_dir() / "term";
  const std::string table = sections_file("refined.csv", "# blade_count = 22\n", two_surfaces(), 20);
  const pid_t pid = hbtrack::test::spawn_cli({"make-blade", "-q", "--geometry", table, "--refine", "3", "-o", out.string()});
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto t0 = std::chrono::steady_clock::now();
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
}

}  // namespace hbtrack_tests::file_blade_input_cli
