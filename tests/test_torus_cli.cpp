// `hbtrack torus` end to end on the nonlinear absorber (examples/nltva.toml at A = 0.12, NS
// points at 1.1096 and 1.2247 rad/s): the branch from NS 1 to NS 2, its envelope against long
// time integrations (`hbtrack simulate`) started from rest inside the band, and one-line errors
// for bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_torus_cli {

namespace fs = std::filesystem;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;

namespace {

const std::string kAbsorber = hbtrack::test::source_path("examples/nltva.toml");

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("hbtrack_torus_" + name + "_" + std::to_string(getpid())); }

// A frc result of the absorber (two NS points), shared per process.
fs::path absorber_frc() {
  static const fs::path dir = [] {
    const fs::path d = temp("frc");
    fs::remove_all(d);
    const CliRun r = run_cli("frc " + kAbsorber + " -o " + d.string() + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return d;
  }();
  return dir;
}

// The branch row nearest `omega`: time integration runs at a row's own omega (interpolating
// between rows would add its chord error, 0.2 % where the envelope rises steeply past NS 1).
std::map<std::string, double> row_near(const std::vector<std::map<std::string, double>>& rows, double omega) {
  return *std::min_element(rows.begin(), rows.end(),
                           [&](const auto& a, const auto& b) { return std::abs(a.at("omega") - omega) < std::abs(b.at("omega") - omega); });
}

std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

TEST(TorusCli, EnvelopeAgreesWithTimeIntegrationInsideTheBand) {
  const fs::path out = temp("branch");
  fs::remove_all(out);
  const CliRun r = run_cli("torus " + kAbsorber + " --from " + absorber_frc().string() + " --ns 1 --range 1.0:1.3 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = hbtrack::test::csv_records(out / "branch.csv");
  ASSERT_GT(rows.size(), 10u);
  const nlohmann::json s = hbtrack::test::read_json(out / "summary.json");
  EXPECT_EQ(s["stop_reason"], "reached_ns_point");
  EXPECT_EQ(s["options"]["torus"]["ns"], 1);
  EXPECT_EQ(s["options"]["torus"]["harmonics"], nlohmann::json({5, 4}));
  EXPECT_NEAR(s["ns_point"]["omega"].get<double>(), 1.10958, 1e-5);
  EXPECT_NEAR(rows.front().at("omega"), s["ns_point"]["omega"].get<double>(), 1e-15);
  EXPECT_EQ(rows.front().at("size"), 0.0);
  EXPECT_NEAR(rows.back().at("omega"), 1.22470, 1e-4);  // NS 2
  // Time integration from rest at three frequencies of the branch inside the band (no other
  // attractor there at A = 0.12): 2000 periods with dopri5 (relative tolerance 1e-9), the last
  // 400 recorded.
  for (double near : {1.14, 1.18, 1.21}) {
    const std::map<std::string, double> torus = row_near(rows, near);
    const double omega = torus.at("omega");
    const fs::path sim = temp("sim");
    fs::remove_all(sim);
    const CliRun t = run_cli("simulate " + kAbsorber + " --omega " + exact(omega) +
                             " --method dopri5 --max-periods 2000 --record-periods 400 -q -o " + sim.string());
    // Quasi-periodic: no periodic steady state within the budget, the run says so (exit 1).
    ASSERT_EQ(t.exit_code, 1) << t.err;
    EXPECT_EQ(hbtrack::test::read_json(sim / "summary.json")["stop_reason"], "max_periods");
    const auto signal = hbtrack::test::csv_records(sim / "signals.csv");
    const size_t half = signal.size() / 2;
    for (const std::string dof : {"x1", "x2"}) {
      // Extremes of the first and last 200 recorded periods, and of all 400.
      double early_max = -1e300, late_max = -1e300, max = -1e300, min = 1e300;
      for (size_t i = 0; i < signal.size(); ++i) {
        const double x = signal[i].at(dof);
        double& window_max = i < half ? early_max : late_max;
        window_max = std::max(window_max, x);
        max = std::max(max, x), min = std::min(min, x);
      }
      const double torus_max = torus.at("max_" + dof), torus_min = torus.at("min_" + dof);
      std::printf("omega %.5f %s: simulate [%.5f, %.5f], torus [%.5f, %.5f]: %+.3f %%, %+.3f %%\n", omega, dof.c_str(), min, max, torus_min,
                  torus_max, 100 * (torus_min / min - 1), 100 * (torus_max / max - 1));
      // After the transient (1600 periods, about 140 turns in the second phase): the first 200
      // recorded periods reach the same extreme as the last 200, up to how closely 200 periods
      // come to the torus' extreme (measured 1.8e-3 relative at 1.139, where omega2 / omega is
      // near 1/11 and the orbit winds slowly round the torus; 2e-4 elsewhere).
      EXPECT_NEAR(early_max, late_max, 5e-3 * max);
      // The issue asks 2 %; measured within 0.03 % over the 400 periods: the torus' truncation
      // (H2 = 4 to 6 moves the envelope by up to 0.03 %) and the extremes of a finite window of
      // samples make up that. 0.2 % leaves room, not more.
      EXPECT_NEAR(torus_max, max, 2e-3 * std::abs(max));
      EXPECT_NEAR(torus_min, min, 2e-3 * std::abs(min));
    }
    fs::remove_all(sim);
  }
  fs::remove_all(out);
}

TEST(TorusCli, BadInputIsOneLineNamingTheFlag) {
  const std::string base = "torus " + kAbsorber + " --from " + absorber_frc().string() + " -q -o " + temp("bad").string();
  const struct {
    std::string flags, message;
  } cases[] = {
      {" --ns 3 --range 1.0:1.3", "--ns: 3 is beyond the 2 NS points of"},
      {" --ns 1 --range 1.2:1.3", "--range: must contain the NS point's omega"},
      {" --ns 1 --range 1.3:1.0", "--range: must be LO:HI with LO < HI"},
      {" --ns 1 --range 1.0:1.3 --harmonics 5", "--harmonics: expected two integers A,B, got '5'"},
      {" --ns 1 --range 1.0:1.3 --samples 64,5", "--samples: must be N1 >= 2 H1 + 1 = 11 and N2 >= 2 H2 + 1 = 9"},
      {" --ns 0 --range 1.0:1.3", "--ns"},
      {" --ns 1 --range 1.0:1.3 --harmonics 40,30",
       "--harmonics: the torus would have 9883 unknowns (2 retained dofs x 4941 coefficients), at most 8000"},
      {" --ns 1 --range 1.0:1.3 --samples 4096,4096", "--samples: the grid of 16777216 samples times 99 coefficients is above 8388608"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli(base + c.flags);
    EXPECT_EQ(r.exit_code, 2) << c.flags << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.flags << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(temp("bad")));
}

}  // namespace hbtrack_tests::file_torus_cli
