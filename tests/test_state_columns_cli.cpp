// states.csv names every dof's harmonics (docs/outputs.md), the condensed dofs too; folders written
// before, with the unknowns x0, x1, ..., still restart an analysis; and `frc --element-forces`
// writes the elements' forces, recomputed here from the states by the element's own law.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_state_columns_cli {

namespace fs = std::filesystem;
using hbtrack::test::csv_header;
using hbtrack::test::csv_records;
using hbtrack::test::file_bytes;
using hbtrack::test::fresh_temp_dir;
using hbtrack::test::run_cli;

namespace {

// NAME_h0, NAME_c1, NAME_s1, ..., NAME_cH, NAME_sH.
std::vector<std::string> harmonic_columns(const std::string& name, int harmonics) {
  std::vector<std::string> columns{name + "_h0"};
  for (int k = 1; k <= harmonics; ++k)
    for (const char* part : {"_c", "_s"}) {
      std::string column = name;
      column += part;
      column += std::to_string(k);
      columns.push_back(column);
    }
  return columns;
}

// Two dofs, x1 forced and linear (condensed out of the unknowns), x2 on the contact (retained),
// H = 10: a short NFRC below the contact resonance.
const std::string kTwoDofRange = " --set continuation.omega_end=1.0 -q";

}  // namespace

TEST(StateColumns, NameEveryDofsHarmonicsTheCondensedOnesToo) {
  const fs::path dir = fresh_temp_dir("hbtrack_state_columns");
  const auto r = run_cli("frc " + hbtrack::test::source_path("examples/two_dof_contact.toml") + kTwoDofRange + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> expected{"omega"};
  for (const char* dof : {"x1", "x2"})
    for (const std::string& column : harmonic_columns(dof, 10)) expected.push_back(column);
  EXPECT_EQ(csv_header(dir / "states.csv"), expected);
  EXPECT_EQ(csv_header(dir / "special_states.csv"), expected);
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir / "summary.json"));
  EXPECT_EQ(summary["options"]["harmonic_balance"]["retained_dofs"], nlohmann::json::array({"x2"}));
  // The condensed dof is recovered: its motion is not zero (it carries the forcing).
  const auto states = csv_records(dir / "states.csv");
  ASSERT_FALSE(states.empty());
  EXPECT_GT(std::hypot(states.back().at("x1_c1"), states.back().at("x1_s1")), 0.0);
  fs::remove_all(dir);
}

TEST(StateColumns, AFolderWithTheEarlierUnknownColumnsRestartsAsTheNewOne) {
  const fs::path dir = fresh_temp_dir("hbtrack_state_layouts");
  const std::string two_dof = hbtrack::test::source_path("examples/two_dof_contact.toml");
  const fs::path fresh = dir / "new", old = dir / "old";
  ASSERT_EQ(run_cli("frc " + two_dof + kTwoDofRange + " -o " + fresh.string()).exit_code, 0);
  // The same folder as hbtrack wrote it before the dof columns: omega, then the unknowns x0, x1,
  // ... = x2's [a0, a1, b1, ..., a10, b10] (x2 the only retained dof), the mean as a0 = 2 x2_h0.
  fs::create_directories(old);
  for (const char* file : {"summary.json", "branch.csv", "special_states.csv"}) fs::copy_file(fresh / file, old / file);
  const std::vector<std::string> x2 = harmonic_columns("x2", 10);
  std::ofstream out(old / "states.csv");
  out << "omega";
  for (size_t i = 0; i < x2.size(); ++i) out << ",x" << i;
  out << "\n";
  for (const auto& row : csv_records(fresh / "states.csv")) {
    char cell[40];
    std::snprintf(cell, sizeof cell, "%.17g", row.at("omega"));
    out << cell;
    for (const std::string& column : x2) {
      std::snprintf(cell, sizeof cell, "%.17g", column == "x2_h0" ? 2 * row.at(column) : row.at(column));
      out << "," << cell;
    }
    out << "\n";
  }
  out.close();
  // Continued from the same point of either folder: the same branch, byte for byte.
  const std::string from = " --point 5 --set continuation.omega_end=1.1 -q -o ";
  const auto a = run_cli("frc " + two_dof + " --from " + fresh.string() + from + (dir / "from_new").string());
  const auto b = run_cli("frc " + two_dof + " --from " + old.string() + from + (dir / "from_old").string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  for (const char* file : {"branch.csv", "states.csv"})
    EXPECT_EQ(file_bytes(dir / "from_new" / file), file_bytes(dir / "from_old" / file)) << file;
  // A states.csv of another case names the column it lacks, in one line.
  std::ofstream(old / "states.csv") << "omega,y_h0,y_c1\n1,0,0\n1,0,0\n1,0,0\n1,0,0\n1,0,0\n1,0,0\n";
  const auto other = run_cli("frc " + two_dof + " --from " + old.string() + from + (dir / "from_other").string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("states.csv:1: no column x2_h0"), std::string::npos) << other.err;
  EXPECT_EQ(std::count(other.err.begin(), other.err.end(), '\n'), 1) << other.err;
  fs::remove_all(dir);
}

// Duffing's cubic spring f = 0.1 x^3 at H = 7, N = 64: x^3 has harmonics up to 21 < N/2 = 32, so
// the AFT has no aliasing and its force harmonics are the exact ones of x(t)^3, which this test
// takes from a fine grid of 1024 instants: agreement to round-off. The max and min are over the
// AFT's 64 instants, recomputed at the same instants.
TEST(ElementForces, AreTheLawAppliedToTheStatesHarmonics) {
  const fs::path dir = fresh_temp_dir("hbtrack_element_forces");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  const auto r = run_cli("frc " + duffing + " --element-forces -q -o " + (dir / "with").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  constexpr int kHarmonics = 7, kSamples = 64, kFine = 1024;
  std::vector<std::string> expected{"omega"};
  for (const std::string& column : harmonic_columns("element0_x", kHarmonics)) expected.push_back(column);
  expected.insert(expected.end(), {"element0_x_max", "element0_x_min"});
  ASSERT_EQ(csv_header(dir / "with" / "element_forces.csv"), expected);
  const auto states = csv_records(dir / "with" / "states.csv"), forces = csv_records(dir / "with" / "element_forces.csv");
  ASSERT_EQ(forces.size(), states.size());
  ASSERT_GT(forces.size(), 20u);
  const auto displacement = [&](const std::map<std::string, double>& s, double tau) {
    double x = s.at("x_h0");
    for (int k = 1; k <= kHarmonics; ++k)
      x += s.at("x_c" + std::to_string(k)) * std::cos(k * tau) + s.at("x_s" + std::to_string(k)) * std::sin(k * tau);
    return x;
  };
  const auto law = [](double x) { return 0.1 * x * x * x; };
  for (size_t i = 0; i < forces.size(); ++i) {
    const auto& s = states[i];
    const auto& f = forces[i];
    EXPECT_EQ(f.at("omega"), s.at("omega"));
    double largest = 0, max = -1e300, min = 1e300;
    for (int j = 0; j < kSamples; ++j) {
      const double value = law(displacement(s, 2 * std::numbers::pi * j / kSamples));
      max = std::max(max, value), min = std::min(min, value), largest = std::max(largest, std::abs(value));
    }
    const double tolerance = 1e-12 * largest;  // round-off of sums of ~64 to 1024 terms of size `largest`
    EXPECT_NEAR(f.at("element0_x_max"), max, tolerance) << "row " << i;
    EXPECT_NEAR(f.at("element0_x_min"), min, tolerance) << "row " << i;
    std::vector<double> cosine(kHarmonics + 1, 0.0), sine(kHarmonics + 1, 0.0);
    for (int j = 0; j < kFine; ++j) {
      const double tau = 2 * std::numbers::pi * j / kFine, value = law(displacement(s, tau));
      for (int k = 0; k <= kHarmonics; ++k)
        cosine[k] += 2.0 / kFine * value * std::cos(k * tau), sine[k] += 2.0 / kFine * value * std::sin(k * tau);
    }
    EXPECT_NEAR(f.at("element0_x_h0"), 0.5 * cosine[0], tolerance) << "the mean, row " << i;
    for (int k = 1; k <= kHarmonics; ++k) {
      EXPECT_NEAR(f.at("element0_x_c" + std::to_string(k)), cosine[k], tolerance) << "row " << i << " k " << k;
      EXPECT_NEAR(f.at("element0_x_s" + std::to_string(k)), sine[k], tolerance) << "row " << i << " k " << k;
    }
  }
  // Asking for the forces changes nothing else.
  ASSERT_EQ(run_cli("frc " + duffing + " -q -o " + (dir / "without").string()).exit_code, 0);
  for (const char* file : {"branch.csv", "states.csv", "stability.csv"})
    EXPECT_EQ(file_bytes(dir / "with" / file), file_bytes(dir / "without" / file)) << file;
  EXPECT_FALSE(fs::exists(dir / "without" / "element_forces.csv"));
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_state_columns_cli
