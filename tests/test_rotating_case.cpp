// [rotation] in a case file: K(Omega) and C + Omega G built from [model] Kg1, Mspin, G at the
// speed (a number or a named parameter), the speed's parameter refused to continuations, the
// one-line errors of wrong inputs; and the Campbell diagram of `modes --speeds` against the
// analytic one of a point mass on isotropic springs in the rotating frame, w0 -+ Omega.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/campbell.hpp"
#include "hbtrack/runs/memory_sink.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_rotating_case {

namespace {

using namespace hbtrack;
namespace fs = std::filesystem;

// A point mass m = 2 on springs k = 200 in the plane normal to the axis (x, y), w0 = 10 rad/s:
// in the rotating frame M_spin = m I, G = 2 m [[0, -1], [1, 0]], no stress stiffening.
const char* kPointMass = R"(
[model]
dofs = ["x", "y"]
M = [[2.0, 0.0], [0.0, 2.0]]
K = [[200.0, 0.0], [0.0, 200.0]]
Kg1 = KG1
Mspin = [[2.0, 0.0], [0.0, 2.0]]
G = GYRO
[rotation]
speed = SPEED
[damping]
C = [[0.1, 0.0], [0.0, 0.1]]
[parameters]
spin = 3.0
[continuation]
omega_start = 5.0
omega_end = 15.0
)";

fs::path write_case(const std::string& name, const std::map<std::string, std::string>& replacements, const char* base = kPointMass) {
  std::string text = base;
  const std::map<std::string, std::string> defaults{
      {"KG1", "[[0.0, 0.0], [0.0, 0.0]]"}, {"GYRO", "[[0.0, -4.0], [4.0, 0.0]]"}, {"SPEED", "\"spin\""}};
  for (const auto& [key, value] : defaults) {
    const auto given = replacements.find(key);
    if (const size_t at = text.find(key); at != std::string::npos)
      text.replace(at, key.size(), given == replacements.end() ? value : given->second);
  }
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_rotating_case_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / (name + ".toml");
  std::ofstream(p) << text;
  return p;
}

TEST(RotatingCase, StiffnessAndDampingAtTheSpeedOfANamedParameter) {
  const CaseDefinition c = load_case(write_case("named", {{"KG1", "[[1.0, 0.5], [0.5, 3.0]]"}}).string());
  ASSERT_TRUE(c.rotation.has_value());
  EXPECT_EQ(c.rotation->speed, 3.0);
  EXPECT_EQ(c.rotation->speed_parameter, "spin");
  Eigen::Matrix2d k;
  k << 200 + 9 * (1.0 - 2.0), 9 * 0.5, 9 * 0.5, 200 + 9 * (3.0 - 2.0);
  EXPECT_LT((c.model.stiffness - k).cwiseAbs().maxCoeff(), 1e-12);
  Eigen::Matrix2d damping;
  damping << 0.1, -12.0, 12.0, 0.1;
  EXPECT_LT((c.model.damping - damping).cwiseAbs().maxCoeff(), 1e-12);
  // --set changes the speed: the model is built again.
  EXPECT_EQ(load_case(write_case("named", {}).string(), {"spin=5"}).model.stiffness(0, 0), 200 - 2.0 * 25);
  // A continuation or a settings override cannot vary it: the model would not follow.
  try {
    parameter_index(c.parameters, "spin", "--param");
    ADD_FAILURE() << "continuation in the speed accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("--param: 'spin' is the rotation speed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(with_overrides(c, {"spin=4"}), CaseError);
  EXPECT_EQ(parameter_index(c.parameters, "amplitude", "--param"), c.parameters.find("amplitude"));
}

// Each wrong input: one line naming the file, its line, the field and the rule.
TEST(RotatingCase, WrongInputsGiveOneLineErrors) {
  struct Bad {
    std::map<std::string, std::string> replacements;
    const char* phrase;
  };
  const Bad cases[] = {
      {{{"SPEED", "-1.0"}}, "rotation.speed: must be >= 0"},
      {{{"SPEED", "\"omega_rot\""}}, "rotation.speed: unknown parameter 'omega_rot'"},
      {{{"KG1", "[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]"}}, "model.Kg1: expected 2x2"},
      {{{"KG1", "{ file = \"missing_Kg1.mtx\" }"}}, "model.Kg1.file: file"},
      {{{"KG1", "[[0.0, 1.0], [0.0, 0.0]]"}}, "model.Kg1: must be symmetric"},
      {{{"GYRO", "[[0.0, 4.0], [4.0, 0.0]]"}}, "model.G: must be skew-symmetric"},
      {{{"SPEED", "20.0"}}, "rotation.speed: K + Omega^2 (Kg1 - Mspin) is not positive definite"},
  };
  for (const Bad& bad : cases) {
    const fs::path path = write_case("bad", bad.replacements);
    try {
      load_case(path.string());
      ADD_FAILURE() << "accepted: " << bad.phrase;
    } catch (const CaseError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(message.rfind(path.string() + ":", 0), 0u) << message;
      EXPECT_NE(message.find(bad.phrase), std::string::npos) << message;
    }
  }
  // The speed read from a parameter names the parameter.
  std::string negative = kPointMass;
  negative.replace(negative.find("spin = 3.0"), 10, "spin = -2.0");
  try {
    load_case(write_case("negative", {}, negative.c_str()).string());
    ADD_FAILURE() << "negative speed accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("parameters.spin (the rotation speed): must be >= 0"), std::string::npos) << e.what();
  }
  // The rotating matrices without [rotation], and [rotation] without Mspin.
  std::string without = kPointMass;
  without.replace(without.find("[rotation]\nspeed = SPEED\n"), 24, "");
  try {
    load_case(write_case("without", {}, without.c_str()).string());
    ADD_FAILURE() << "Kg1 without [rotation] accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("model.Kg1: a rotating model's matrix"), std::string::npos) << e.what();
  }
  std::string no_spin = kPointMass;
  no_spin.replace(no_spin.find("Mspin = [[2.0, 0.0], [0.0, 2.0]]\n"), 33, "");
  try {
    load_case(write_case("no_spin", {}, no_spin.c_str()).string());
    ADD_FAILURE() << "[rotation] without Mspin accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("model.Mspin: missing"), std::string::npos) << e.what();
  }
}

// In the rotating frame the mass's two circular modes are at w0 - Omega and w0 + Omega (the
// stiffness softens by m Omega^2, the Coriolis force splits them): exact, to the eigensolver's
// round-off. Below Omega = w0 = 10 rad/s.
TEST(RotatingCase, CampbellDiagramOfAPointMassIsW0PlusMinusOmega) {
  const CaseDefinition c = load_case(write_case("campbell", {}).string());
  runs::CampbellOptions o;
  o.speeds = runs::parse_speeds("0:8:9", "--speeds");
  o.count = 2;
  o.engine_orders = 2;
  runs::MemorySink sink;
  const runs::RunReport report = runs::campbell(c, o, sink);
  ASSERT_TRUE(report.success()) << report.failure;
  ASSERT_EQ(sink.tables().size(), 1u);
  ASSERT_EQ(sink.tables().front().first, "campbell");
  const auto& rows = sink.tables().front().second.rows;
  ASSERT_EQ(rows.size(), 9u);
  for (const auto& row : rows) {
    const double speed = row[0], low = std::min(row[1], row[2]), high = std::max(row[1], row[2]);
    EXPECT_NEAR(low, 10.0 - speed, 1e-9) << speed;
    EXPECT_NEAR(high, 10.0 + speed, 1e-9) << speed;
  }
  // The lower mode meets 1 x Omega at w0 / 2 = 5 rad/s (10 - Omega = Omega), linear in the table.
  bool found = false;
  for (const auto& x : report.summary["engine_order_crossings"])
    if (x["engine_order"] == 1) {
      EXPECT_NEAR(x["speed"].get<double>(), 5.0, 1e-9);
      found = true;
    }
  EXPECT_TRUE(found);
  EXPECT_THROW(runs::parse_speeds("0:8", "--speeds"), CaseError);
  EXPECT_THROW(runs::parse_speeds("5:1:3", "--speeds"), CaseError);
}

// The frequencies of (K(W) + i w W G - w^2 M) phi = 0 are those of its transpose, with -G: the
// Campbell diagram of rotor 67 with G and with -G agree to round-off. (The first-order form
// [0 I; -M^-1 K, -M^-1 W G] missed this by 8e-5: its scaling, not the physics.)
TEST(RotatingCase, CampbellDiagramIsTheSameForEitherSenseOfTheCoriolisMatrix) {
  const CaseDefinition c = load_case(hbtrack::test::source_path("examples/rotor67/design_speed.toml"));
  ASSERT_TRUE(c.rotation.has_value());
  ASSERT_GT(c.rotation->gyroscopic.size(), 0);
  CaseDefinition reversed = c;
  reversed.rotation->gyroscopic *= -1.0;
  runs::CampbellOptions o;
  o.speeds = runs::parse_speeds("0:1680:22", "--speeds");
  o.count = 4;
  runs::MemorySink a, b;
  ASSERT_TRUE(runs::campbell(c, o, a).success());
  ASSERT_TRUE(runs::campbell(reversed, o, b).success());
  const auto& rows_a = a.tables().front().second.rows;
  const auto& rows_b = b.tables().front().second.rows;
  ASSERT_EQ(rows_a.size(), rows_b.size());
  for (size_t r = 0; r < rows_a.size(); ++r)
    for (size_t k = 1; k < rows_a[r].size(); ++k) EXPECT_NEAR(rows_a[r][k] / rows_b[r][k], 1.0, 1e-10) << rows_a[r][0] << " mode " << k;
  // G moves the frequencies (by 0.07 % on 1B at 1680 rad/s): the check is not of a zero effect.
  CaseDefinition without = c;
  without.rotation->gyroscopic.resize(0, 0);
  runs::MemorySink plain;
  ASSERT_TRUE(runs::campbell(without, o, plain).success());
  EXPECT_GT(std::abs(plain.tables().front().second.rows.back()[1] / rows_a.back()[1] - 1.0), 1e-4);
}

}  // namespace

}  // namespace hbtrack_tests::file_rotating_case
