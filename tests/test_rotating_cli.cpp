// The rotating blade through the command-line tool, as a user runs it: make-blade --rotating ->
// reduce --rotating --check-speed -> a case with [rotation] -> modes and modes --speeds; the
// reduced matrices are T^T A T of the full ones, and wrong inputs fail with exit 2 and one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "cli_support.hpp"
#include "hbtrack/io/matrix_market.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_rotating_cli {

namespace {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::read_json;
using nlohmann::json;

class RotatingCli : public hbtrack::test::ScratchFolderTest {
 protected:
  RotatingCli() : ScratchFolderTest("hbtrack_rotating_cli") {}
  static CliRun run(const std::string& args) { return hbtrack::test::run_cli(args); }
};

Eigen::MatrixXd dense(const std::string& file) { return Eigen::MatrixXd(hbtrack::read_matrix_market_sparse(file)); }

TEST_F(RotatingCli, MakeBladeReduceAndTheCampbellDiagramOfTheCase) {
  CliRun r = run("make-blade --rotating -q -o " + path("fe"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json blade = read_json(path("fe/summary.json"));
  EXPECT_EQ(blade["rotation"]["axis_direction"][0], -1.0);  // the parametric blade runs towards -theta about X
  r = run("reduce --mass " + path("fe/M.mtx") + " --stiffness " + path("fe/K.mtx") + " --nodes " + path("fe/nodes.csv") +
          " --boundary-file " + path("fe/boundary.txt") + " --modes 12 --rotating --check-speed 1680 -q -o " + path("rom"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The reduced matrices are the full ones on the basis T.
  const Eigen::MatrixXd t = dense(path("rom/T.mtx"));
  for (const char* name : {"Kg1.mtx", "Mspin.mtx", "G.mtx"}) {
    const Eigen::MatrixXd expected = t.transpose() * dense(path(std::string("fe/") + name)) * t;
    EXPECT_LT((dense(path(std::string("rom/") + name)) - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff()) << name;
  }
  const json at = read_json(path("rom/summary.json"))["rotation"]["check_at_speed"];
  EXPECT_EQ(at["speed"], 1680.0);
  for (int k = 0; k < 3; ++k) EXPECT_LT(std::abs(at["relative_difference_of_reduced"][k].get<double>()), 5e-4) << k;

  std::ofstream(path("rotating.toml")) << "[model]\ndofs = { file = \"rom/summary.json\" }\nM = { file = \"rom/M.mtx\" }\n"
                                          "K = { file = \"rom/K.mtx\" }\nKg1 = { file = \"rom/Kg1.mtx\" }\n"
                                          "Mspin = { file = \"rom/Mspin.mtx\" }\nG = { file = \"rom/G.mtx\" }\n"
                                          "[rotation]\nspeed = \"speed\"\n[parameters]\nspeed = 1680.0\n"
                                          "[continuation]\nomega_start = 2000.0\nomega_end = 3000.0\n";
  r = run("modes " + path("rotating.toml") + " --speeds 0:1680:8 --count 3 -q -o " + path("campbell"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json campbell = read_json(path("campbell/summary.json"));
  EXPECT_EQ(campbell["kind"], "campbell");
  std::ifstream table(path("campbell/campbell.csv"));
  std::string header;
  std::getline(table, header);
  EXPECT_EQ(header, "speed,1B,2B,1T");  // named by make-blade, through reduce's summary
  // The last row is the speed of the case: 1B as `modes` gives it at 1680 rad/s without G, within
  // G's effect (0.1 %).
  r = run("modes " + path("rotating.toml") + " --count 1 -q -o " + path("modes"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double w1 = read_json(path("modes/summary.json"))["natural_frequencies"][0];
  EXPECT_NEAR(campbell["frequencies_at_highest_speed"][0].get<double>() / w1, 1.0, 1e-3);
  EXPECT_NEAR(w1 / at["reduced_frequencies"][0].get<double>(), 1.0, 1e-12);

  // Wrong inputs: exit 2, one line naming the flag or field. plain/: M and K without the rotating matrices.
  fs::create_directories(path("plain"));
  for (const char* name : {"M.mtx", "K.mtx"}) fs::copy_file(path(std::string("fe/") + name), path(std::string("plain/") + name));
  const std::pair<std::string, std::string> bad[] = {
      {"modes " + path("rotating.toml") + " --speeds 0:1680 -o " + path("x"), "--speeds: '0:1680' must be LO:HI:N"},
      {"modes " + path("rotating.toml") + " --set speed=-5 -o " + path("x"), "parameters.speed (the rotation speed): must be >= 0"},
      {"continue " + path("rotating.toml") + " --param speed --omega 2500 --range 0:100 -o " + path("x"),
       "--param: 'speed' is the rotation speed"},
      {"reduce --mass " + path("plain/M.mtx") + " --stiffness " + path("plain/K.mtx") + " --nodes " + path("fe/nodes.csv") +
           " --boundary-file " + path("fe/boundary.txt") + " --rotating -o " + path("x"),
       "plain/Kg1.mtx not found (write it with make-blade --rotating)"},
      {"reduce --mass " + path("fe/M.mtx") + " --stiffness " + path("fe/K.mtx") + " --nodes " + path("fe/nodes.csv") + " --boundary-file " +
           path("fe/boundary.txt") + " --check-speed 100 -o " + path("x"),
       "--check-speed: needs --rotating"},
      {"modes " + hbtrack::test::source_path("examples/duffing.toml") + " --speeds 0:1:3 -o " + path("x"), "the case has no [rotation]"},
  };
  for (const auto& [args, phrase] : bad) {
    r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(phrase), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace

}  // namespace hbtrack_tests::file_rotating_cli
