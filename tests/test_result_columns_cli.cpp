// branch.csv's harmonic columns (hK_NAME, phaseK_NAME) and stability.csv, recomputed from what
// the same run wrote to states.csv and from the Floquet exponents' own definitions.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_result_columns_cli {

namespace fs = std::filesystem;
using hbtrack::test::csv_header;
using hbtrack::test::run_cli;

namespace {

std::vector<std::vector<double>> csv_numbers(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// prefix K _ name, appended rather than with operator+ (GCC 12 -O3 warns falsely about
// `"h" + std::to_string(k)`: -Wstringop-overflow).
std::string column(const char* prefix, int k, const char* name) {
  std::string c = prefix;
  c += std::to_string(k);
  c += '_';
  c += name;
  return c;
}

std::map<std::string, size_t> column_index(const std::vector<std::string>& header) {
  std::map<std::string, size_t> index;
  for (size_t j = 0; j < header.size(); ++j) index[header[j]] = j;
  return index;
}

// Duffing at H = 7: one dof x, so states.csv holds its harmonics x_h0, x_c1, x_s1, ..., x_c7,
// x_s7 (nothing condensed), and it folds, so the branch has stable and unstable points.
class ResultColumns : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = fs::temp_directory_path() / ("hbtrack_result_columns_" + std::to_string(getpid()));
    fs::remove_all(out_);
    const auto r = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " -o " + out_.string() + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(out_); }
  static inline fs::path out_;
  static constexpr int kHarmonics = 7;
};

TEST_F(ResultColumns, HistoricalColumnsComeFirstThenEveryHarmonicAndPhase) {
  const std::vector<std::string> header = csv_header(out_ / "branch.csv");
  const std::vector<std::string> first{"omega", "stable", "max_x", "min_x", "h1_x"};
  ASSERT_GE(header.size(), first.size());
  EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 5), first);
  std::vector<std::string> appended{"h0_x"};
  for (int k = 2; k <= kHarmonics; ++k) appended.push_back(column("h", k, "x"));
  for (int k = 1; k <= kHarmonics; ++k) appended.push_back(column("phase", k, "x"));
  EXPECT_EQ(std::vector<std::string>(header.begin() + 5, header.end()), appended);
}

TEST_F(ResultColumns, MagnitudesAndPhasesAreThoseOfTheStatesCoefficients) {
  const auto branch = csv_numbers(out_ / "branch.csv"), states = csv_numbers(out_ / "states.csv");
  const auto col = column_index(csv_header(out_ / "branch.csv"));
  std::vector<std::string> state_columns{"omega", "x_h0"};
  for (int k = 1; k <= kHarmonics; ++k)
    for (const char* part : {"x_c", "x_s"}) {
      std::string name = part;
      name += std::to_string(k);
      state_columns.push_back(name);
    }
  ASSERT_EQ(csv_header(out_ / "states.csv"), state_columns);
  ASSERT_EQ(branch.size(), states.size());
  ASSERT_GT(branch.size(), 20u);
  for (size_t i = 0; i < branch.size(); ++i) {
    const auto& b = branch[i];
    const auto& s = states[i];  // omega, the mean, a1, b1, ..., a7, b7
    ASSERT_EQ(s.size(), 2u + 2 * kHarmonics);
    EXPECT_EQ(b[col.at("omega")], s[0]);
    // Both files print 17 digits of the same doubles: the same formulas agree to round-off
    // (4 ulps of the largest coefficient, for hypot and atan2 of identical inputs).
    const double scale = std::abs(b[col.at("max_x")]) + std::abs(b[col.at("min_x")]);
    const double tolerance = 4 * std::numeric_limits<double>::epsilon() * scale;
    EXPECT_NEAR(b[col.at("h0_x")], s[1], tolerance) << "both the mean, row " << i;
    double largest = std::abs(s[1]);
    for (int k = 1; k <= kHarmonics; ++k)
      largest = std::max(largest, std::hypot(s[static_cast<size_t>(2 * k)], s[static_cast<size_t>(2 * k + 1)]));
    for (int k = 1; k <= kHarmonics; ++k) {
      const double a = s[static_cast<size_t>(2 * k)], bk = s[static_cast<size_t>(2 * k + 1)];
      EXPECT_NEAR(b[col.at(column("h", k, "x"))], std::hypot(a, bk), tolerance) << "row " << i << " k " << k;
      const double h = b[col.at(column("h", k, "x"))], phase = b[col.at(column("phase", k, "x"))];
      if (h <= 1e-12 * largest) {  // round-off (Duffing's even harmonics): no phase to speak of
        EXPECT_EQ(phase, 0.0) << "row " << i << " k " << k;
        continue;
      }
      // The convention itself: a_k cos + b_k sin = h_k cos(k w t - phase_k) at two instants.
      EXPECT_NEAR(h * std::cos(-phase), a, 8 * tolerance) << "row " << i << " k " << k;
      EXPECT_NEAR(h * std::cos(std::numbers::pi / 2 - phase), bk, 8 * tolerance) << "row " << i << " k " << k;
      EXPECT_LE(std::abs(phase), std::numbers::pi);
    }
  }
}

TEST_F(ResultColumns, StabilityTableHoldsTheExponentsThatDecidedStable) {
  const auto branch = csv_numbers(out_ / "branch.csv"), table = csv_numbers(out_ / "stability.csv");
  const auto col = column_index(csv_header(out_ / "branch.csv"));
  EXPECT_EQ(csv_header(out_ / "stability.csv"), (std::vector<std::string>{"point", "omega", "k", "exponent_real", "exponent_imag",
                                                                          "multiplier_real", "multiplier_imag", "method"}));
  std::map<int, std::vector<std::vector<double>>> by_point;
  for (const auto& row : table) by_point[static_cast<int>(row[0])].push_back(row);
  ASSERT_EQ(by_point.size(), branch.size());
  int stable = 0, unstable = 0;
  for (const auto& [point, rows] : by_point) {
    const auto& b = branch.at(static_cast<size_t>(point));
    ASSERT_EQ(rows.size(), 2u) << "a one-dof system has 2 exponents, point " << point;
    const double omega = b[col.at("omega")], period = 2 * std::numbers::pi / omega;
    for (size_t k = 0; k < rows.size(); ++k) {
      EXPECT_EQ(rows[k][1], omega);
      EXPECT_EQ(rows[k][2], static_cast<double>(k));
      if (k > 0) {
        EXPECT_GE(rows[k - 1][3], rows[k][3]) << "decreasing real part, point " << point;
      }
      // Multipliers are exp(exponent T) (floquet.cpp): to round-off of exp, 1e-12 relative.
      const std::complex<double> expected = std::exp(std::complex<double>(rows[k][3], rows[k][4]) * period);
      EXPECT_NEAR(rows[k][5], expected.real(), 1e-12 * std::abs(expected)) << "point " << point;
      EXPECT_NEAR(rows[k][6], expected.imag(), 1e-12 * std::abs(expected)) << "point " << point;
      EXPECT_EQ(rows[k][7], 0.0) << "Hill (code 0) decides on Duffing (a smooth law), point " << point;
    }
    // `stable` is max Re(exponent) <= 1e-9 omega (finish_floquet's tolerance): row k = 0 decides.
    const bool is_stable = rows[0][3] <= 1e-9 * omega;
    EXPECT_EQ(b[col.at("stable")], is_stable ? 1.0 : 0.0) << "point " << point;
    (is_stable ? stable : unstable)++;
  }
  EXPECT_GT(stable, 0);
  EXPECT_GT(unstable, 0);  // Duffing's middle branch, between its two limit points
}

}  // namespace

}  // namespace hbtrack_tests::file_result_columns_cli
