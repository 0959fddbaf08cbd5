// The study's page (apps/hbtrack/study_report.cpp): the isola's time integration gets a section
// of its own, with where on the isola it started and how far from the ends of its stable stretch.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "study_report.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_study_report {

using nlohmann::json;
namespace fs = std::filesystem;

TEST(StudyReport, TheIsolasTimeIntegrationIsReportedWithItsMarginAndItsComparison) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_study_report_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const json isola = {
      {"folder", "isolas_amplitude_5/isola_1"},
      {"point", 90},
      {"omega", 2441.419},
      {"stable_margin", 0.005047},
      {"periods", 200},
      {"converged", false},
      {"last_change", 1.5e-3},
      {"wall_s", 61.2},
      {"outputs", json::array({{{"name", "h1_le"}, {"hbm", 1.0e-3}, {"simulation", 1.012e-3}, {"relative_difference", 0.012}}})}};
  const json summary = {{"case", "rotor67.toml"}, {"stop_reason", "completed"}, {"steps", json::array()}, {"isola_simulation", isola}};
  hbtrack::cli::write_study_report(dir.string(), summary);
  std::ifstream in(dir / "index.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  EXPECT_NE(text.find("## Time integration on an isolated branch"), std::string::npos) << text;
  EXPECT_NE(text.find("From point 90 of [isolas_amplitude_5/isola_1](isolas_amplitude_5/isola_1/) (omega = 2441.42 rad/s)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("0.50 % in omega from its nearer end"), std::string::npos) << text;
  EXPECT_NE(text.find("Not periodic to `simulate`'s criterion"), std::string::npos) << text;
  EXPECT_NE(text.find("| h1_le | 0.001 | 0.001012 | +1.20 % |"), std::string::npos) << text;
  // Without an isola integration, no such section.
  hbtrack::cli::write_study_report(dir.string(), json{{"case", "c.toml"}, {"stop_reason", "completed"}, {"steps", json::array()}});
  std::ifstream again(dir / "index.md");
  std::stringstream without;
  without << again.rdbuf();
  EXPECT_EQ(without.str().find("isolated branch"), std::string::npos);
  fs::remove_all(dir);
}

TEST(StudyReport, EachTorusIsListedWithHowItEndedOrWhyItWasSkipped) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_study_report_tori_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const json closed = {{"ns", 1},
                       {"omega", 1.109577},
                       {"other_ns", 2},
                       {"other_omega", 1.224699},
                       {"folder", "torus_ns1"},
                       {"exit_code", 0},
                       {"points", 36},
                       {"stop_reason", "reached_ns_point"},
                       {"closed_at_ns", 2},
                       {"closed_at_distance", 2.5e-5},
                       {"omega_range", {1.109577, 1.224674}},
                       {"envelope", json::array({{{"name", "x1"}, {"max", 0.699072}, {"omega_at_max", 1.16243}, {"min", -0.699072}}})},
                       {"wall_s", 2.1}};
  json failed = closed;
  failed.update({{"ns", 3}, {"other_ns", 4}, {"folder", "torus_ns3"}, {"exit_code", 1}, {"stop_reason", "no_convergence"}});
  failed.erase("closed_at_ns");
  const json skipped = {{"ns", 5},
                        {"omega", 2.0},
                        {"other_ns", 6},
                        {"other_omega", 2.1},
                        {"folder", "torus_ns5"},
                        {"exit_code", 2},
                        {"skipped", "case.toml: torus: elements[0] (iwan): its force depends on its past"}};
  hbtrack::cli::write_study_report(
      dir.string(),
      json{{"case", "c.toml"}, {"stop_reason", "completed"}, {"steps", json::array()}, {"tori", json::array({closed, failed, skipped})}});
  std::ifstream in(dir / "index.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  EXPECT_NE(text.find("| NS1 (1.10958) | NS2 (1.2247) | [torus_ns1](torus_ns1/) | 36 | closed at NS2 (last row 2.5e-05 from it in omega) | "
                      "1.10958 to 1.22467 | x1 0.699072 (1.16243), -0.699072 | 2.1 |"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("| [torus_ns3](torus_ns3/) | 36 | no_convergence (exit 1) |"), std::string::npos) << text;
  EXPECT_NE(text.find("| torus_ns5 | | skipped: case.toml: torus: elements[0] (iwan): its force depends on its past |"), std::string::npos)
      << text;
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_study_report
