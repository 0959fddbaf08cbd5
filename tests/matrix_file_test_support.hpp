#pragma once
// Shared by the Matrix Market and .mat reader tests: a private temporary directory per test, the
// one-line error check both readers promise, and a small matrix with zeros, negatives and a tiny
// entry.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace hbtrack::test {

namespace fs = std::filesystem;

inline Eigen::SparseMatrix<double> sparse_from(const Eigen::MatrixXd& dense) { return dense.sparseView(); }

// Each test gets its own directory so parallel runs (ctest -j) never share files.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string test_name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : test_name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    std::random_device entropy;
    dir_ =
        fs::temp_directory_path() / ("hbtrack_matrix_readers_" + test_name + "_" + std::to_string(entropy()) + std::to_string(entropy()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::string path_for(const std::string& filename) const { return (dir_ / filename).string(); }

  std::string write_text(const std::string& filename, const std::string& content) const {
    const std::string path = path_for(filename);
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
  }

  fs::path dir_;
};

// Checks the promised error shape: std::runtime_error, one line, naming the file and the problem.
template <class Action>
inline void expect_error(Action&& action, const std::string& path, const std::string& phrase) {
  try {
    std::forward<Action>(action)();
    ADD_FAILURE() << "expected std::runtime_error containing '" << phrase << "'";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

inline Eigen::MatrixXd example_matrix() {
  Eigen::MatrixXd matrix(3, 4);
  matrix << 4.0, 0.0, -1.5, 0.0,  //
      0.0, 2.25, 0.0, 1e-12,      //
      7.0, 0.0, 0.0, -3.0;
  return matrix;
}

}  // namespace hbtrack::test
