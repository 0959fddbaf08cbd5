// `hbtrack frc` reports the friction loop gain of each frictional contact in summary.json and
// warns, once per contact, where it exceeds 1; the same case turning the other way does not.
// On a 3-dof tip node and on the rotor 67 case.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_friction_loop_gain_cli {

namespace {

using hbtrack::test::fresh_temp_dir;
using hbtrack::test::run_cli;

// A tip node coupled radially to circumferentially (G = K^-1: G_rr = 5/9, G_rt = 4/9) with
// mu = 1.5: ratio 1.2 or -1.2 by the sense of rotation, gain k G_rr (ratio - 1) = 1.11 or -12.2. The
// casing stays out of reach (clearance 10), so the NFRC is the linear one and quick.
std::filesystem::path write_case(const std::filesystem::path& dir, double engine_order) {
  const std::filesystem::path path = dir / ("tip_" + std::to_string(static_cast<int>(engine_order)) + ".toml");
  std::ofstream(path) << "[model]\ndofs = [\"tip_r\", \"tip_t\", \"tip_z\"]\nM = { diagonal = [1.0, 1.0, 1.0] }\n"
                         "K = [[5.0, -4.0, 0.0], [-4.0, 5.0, 0.0], [0.0, 0.0, 1.0]]\n"
                         "[damping]\nrayleigh = [0.0, 0.02]\n"
                         "[[forcing]]\ndof = \"tip_r\"\ncos = 0.1\n"
                         "[parameters]\nmu = 1.5\n"
                         "[[elements]]\ntype = \"tip_contact\"\ndofs = [\"tip_r\", \"tip_t\", \"tip_z\"]\nlaw = \"sqrt\"\n"
                         "stiffness = 10.0\nclearance = 10.0\nwidth = 0.1\nmu = \"mu\"\nradius = 0.3\nengine_order = "
                      << engine_order
                      << "\n[harmonic_balance]\nharmonics = 3\n"
                         "[continuation]\nomega_start = 0.5\nomega_end = 1.5\n";
  return path;
}

nlohmann::json frc_summary(const std::filesystem::path& out) { return nlohmann::json::parse(std::ifstream(out / "summary.json")); }

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(FrictionLoopGainCli, FrcWritesTheGainAndWarnsOnlyAboveOne) {
  const auto dir = fresh_temp_dir("hbtrack_loop_gain", true);
  // engine_order -1: the casing turns towards -t and drags the tip along +t.
  const hbtrack::test::CliRun pushed = run_cli("frc " + write_case(dir, -1.0).string() + " -o " + (dir / "pushed").string());
  ASSERT_EQ(pushed.exit_code, 0) << pushed.err;
  const nlohmann::json a = frc_summary(dir / "pushed")["friction_loop_gain"];
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0]["element"], 0);
  EXPECT_EQ(a[0]["node"], "tip");
  EXPECT_EQ(a[0]["sense"], 1);
  EXPECT_EQ(a[0]["sense_from"], "law");
  EXPECT_NEAR(a[0]["ratio"].get<double>(), 1.5 * 0.8, 1e-14);
  EXPECT_NEAR(a[0]["gain"].get<double>(), 10.0 * (5.0 / 9.0) * 0.2, 1e-13);
  EXPECT_TRUE(a[0]["self_energising"].get<bool>());
  EXPECT_EQ(count(pushed.err, "friction loop gain"), 1) << pushed.err;
  EXPECT_EQ(count(pushed.err, "Painleve"), 1) << pushed.err;
  EXPECT_EQ(frc_summary(dir / "pushed")["warnings"].size(), 1u);

  const hbtrack::test::CliRun pulled = run_cli("frc " + write_case(dir, 1.0).string() + " -o " + (dir / "pulled").string());
  ASSERT_EQ(pulled.exit_code, 0) << pulled.err;
  const nlohmann::json b = frc_summary(dir / "pulled")["friction_loop_gain"];
  EXPECT_NEAR(b[0]["ratio"].get<double>(), -1.2, 1e-14);
  EXPECT_FALSE(b[0]["self_energising"].get<bool>());
  EXPECT_TRUE(b[0]["critical_stiffness"].is_null());
  EXPECT_EQ(count(pulled.err, "friction loop gain"), 0) << pulled.err;
  std::filesystem::remove_all(dir);
}

// Issue 35's "done when": the nominal rotor 67 case warns for n3 and n4 and for no other node,
// reversed for none. Two points of the NFRC suffice: the gain is written before the first.
TEST(FrictionLoopGainCli, Rotor67WarnsAtN3AndN4InTheGeometrysSenseAndNowhereReversed) {
  const auto dir = fresh_temp_dir("hbtrack_loop_gain_r67", true);
  const std::string frc = "frc " + hbtrack::test::source_path("examples/rotor67/nominal.toml") + " --set continuation.max_points=2";
  const hbtrack::test::CliRun geometry = run_cli(frc + " -o " + (dir / "geometry").string());
  ASSERT_EQ(geometry.exit_code, 0) << geometry.err;
  EXPECT_EQ(count(geometry.err, "friction loop gain"), 2) << geometry.err;
  EXPECT_EQ(count(geometry.err, "(tip_contact n3_r, n3_t): friction loop gain"), 1) << geometry.err;
  EXPECT_EQ(count(geometry.err, "(tip_contact n4_r, n4_t): friction loop gain"), 1) << geometry.err;
  const nlohmann::json gains = frc_summary(dir / "geometry")["friction_loop_gain"];
  ASSERT_EQ(gains.size(), 9u);
  for (const auto& g : gains) EXPECT_EQ(g["self_energising"].get<bool>(), g["node"] == "n3" || g["node"] == "n4") << g["node"];

  std::string reverse;
  for (int i = 0; i < 9; ++i) reverse += " --set elements[" + std::to_string(i) + "].engine_order=1";
  const hbtrack::test::CliRun reversed = run_cli(frc + reverse + " -o " + (dir / "reversed").string());
  ASSERT_EQ(reversed.exit_code, 0) << reversed.err;
  EXPECT_EQ(count(reversed.err, "friction loop gain"), 0) << reversed.err;
  // Held in a variable: a range-for over a member of a temporary reads freed memory.
  const nlohmann::json reversed_summary = frc_summary(dir / "reversed");
  for (const auto& g : reversed_summary["friction_loop_gain"]) EXPECT_FALSE(g["self_energising"].get<bool>()) << g["node"];
  std::filesystem::remove_all(dir);
}

TEST(FrictionLoopGainCli, FrcOfACaseWithoutFrictionHasNoField) {
  const auto dir = fresh_temp_dir("hbtrack_loop_gain_none", true);
  const hbtrack::test::CliRun r =
      run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " -o " + (dir / "duffing").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(frc_summary(dir / "duffing").contains("friction_loop_gain"));
  std::filesystem::remove_all(dir);
}

}  // namespace

}  // namespace hbtrack_tests::file_friction_loop_gain_cli
