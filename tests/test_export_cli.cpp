// `hbtrack export DIR --format h5`: a result folder as one HDF5 file, read back with HDF5's C API
// as any reader would (h5py, h5read): the columns as branch.csv and states.csv print them, the special points and summary.json; and bad
// input refused in one line. (The .mat format is read back with scipy in python/tests/test_export.py.)
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_export_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;
using nlohmann::json;

namespace {

fs::path fresh_dir(const std::string& name) { return hbtrack::test::fresh_temp_dir(name, false); }

// A dataset of doubles, whole (row-major), and its dimensions.
std::vector<double> read_doubles(hid_t file, const std::string& path, std::vector<hsize_t>* dims = nullptr) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << path;
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  std::vector<hsize_t> d(static_cast<size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, d.data(), nullptr);
  std::vector<double> values(static_cast<size_t>(H5Sget_simple_extent_npoints(space)));
  EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0) << path;
  H5Sclose(space);
  H5Dclose(set);
  if (dims) *dims = d;
  return values;
}

// Fixed-length strings (`count` of them, NUL-padded) from a dataset or attribute's raw bytes.
std::vector<std::string> split_fixed(const std::string& bytes, size_t width) {
  std::vector<std::string> texts;
  for (size_t at = 0; at + width <= bytes.size(); at += width) {
    const std::string t = bytes.substr(at, width);
    texts.push_back(t.substr(0, t.find('\0')));
  }
  return texts;
}

std::vector<std::string> read_strings(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << path;
  if (set < 0) return {};
  const hid_t type = H5Dget_type(set), space = H5Dget_space(set);
  const size_t width = H5Tget_size(type);
  std::string bytes(width * static_cast<size_t>(H5Sget_simple_extent_npoints(space)), '\0');
  EXPECT_GE(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), 0) << path;
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(set);
  return split_fixed(bytes, width);
}

std::string read_string_attribute(hid_t file, const std::string& name) {
  const hid_t attribute = H5Aopen(file, name.c_str(), H5P_DEFAULT);
  EXPECT_GE(attribute, 0) << name;
  if (attribute < 0) return "";
  const hid_t type = H5Aget_type(attribute);
  std::string bytes(H5Tget_size(type), '\0');
  EXPECT_GE(H5Aread(attribute, type, bytes.data()), 0) << name;
  H5Tclose(type);
  H5Aclose(attribute);
  return bytes.substr(0, bytes.find('\0'));
}

}  // namespace

TEST(ExportCli, H5HoldsTheTablesSpecialPointsAndSummaryAsTheFolderDoes) {
  // A short NFRC over the resonance at 3 harmonics: both limit points in about 40 points.
  const fs::path folder = fresh_dir("hbtrack_export_h5");
  const CliRun frc = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") +
                             " --set harmonic_balance.harmonics=3 --set continuation.omega_start=1.0 --set continuation.omega_end=1.4 -o " +
                             folder.string() + " -q");
  ASSERT_EQ(frc.exit_code, 0) << frc.err;
  const CliRun exported = run_cli("export " + folder.string() + " --format h5");
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.err.find("results.h5"), std::string::npos) << exported.err;
  const fs::path h5 = folder / "results.h5";
  ASSERT_TRUE(fs::exists(h5));
  EXPECT_FALSE(fs::exists(folder / "results.h5.tmp")) << "the temporary file was renamed into place";

  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // branch.csv prints every double with 17 digits: the file holds the same doubles.
  const auto branch = hbtrack::test::csv_records(folder / "branch.csv");
  ASSERT_GT(branch.size(), 10u);
  const std::vector<double> omega = read_doubles(file, "branch/omega"), max_x = read_doubles(file, "branch/max_x");
  ASSERT_EQ(omega.size(), branch.size());
  ASSERT_EQ(max_x.size(), branch.size());
  for (size_t i = 0; i < branch.size(); ++i) {
    EXPECT_EQ(omega[i], branch[i].at("omega")) << "row " << i;
    EXPECT_EQ(max_x[i], branch[i].at("max_x")) << "row " << i;
  }
  // states.csv: every column (omega, x_h0, x_c1, x_s1, ...) one dataset, as branch.csv's.
  const auto states = hbtrack::test::csv_records(folder / "states.csv");
  for (const char* name : {"x_h0", "x_c1", "x_s3"}) {
    const std::vector<double> column = read_doubles(file, std::string("states/") + name);
    ASSERT_EQ(column.size(), states.size()) << name;
    EXPECT_EQ(column[1], states[1].at(name)) << name;
  }

  const json summary = json::parse(std::ifstream(folder / "summary.json"));
  const std::vector<std::string> summary_json = read_strings(file, "summary_json");
  ASSERT_EQ(summary_json.size(), 1u);
  EXPECT_EQ(json::parse(summary_json[0]), summary);
  EXPECT_EQ(read_string_attribute(file, "stop_reason"), summary["stop_reason"].get<std::string>());
  EXPECT_EQ(read_string_attribute(file, "verb"), "frc");
  ASSERT_EQ(summary["special_points"].size(), 2u);
  EXPECT_EQ(read_strings(file, "special_points/type"), (std::vector<std::string>{"LP", "LP"}));
  const std::vector<double> sp_omega = read_doubles(file, "special_points/omega");
  ASSERT_EQ(sp_omega.size(), 2u);
  EXPECT_EQ(sp_omega[1], summary["special_points"][1]["omega"].get<double>());
  H5Fclose(file);
  fs::remove_all(folder);
}

TEST(ExportCli, RefusesAMissingFolderAndAnUnknownFormatInOneLine) {
  const fs::path folder = fresh_dir("hbtrack_export_bad");
  fs::create_directories(folder);
  const CliRun missing = run_cli("export " + (folder / "absent").string() + " --format h5");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("not a result folder"), std::string::npos) << missing.err;
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  const CliRun unknown = run_cli("export " + folder.string() + " --format hdf");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--format: must be mat or h5, got 'hdf'"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;
  EXPECT_TRUE(fs::is_empty(folder)) << "nothing half-written";
  fs::remove_all(folder);
}

}  // namespace hbtrack_tests::file_export_cli
