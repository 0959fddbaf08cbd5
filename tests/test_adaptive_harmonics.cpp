// Harmonics chosen as the run goes (harmonic_balance.adaptive): the criterion, the NFRC whose H
// changes along the branch against fixed-H runs, and the bad settings' errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "cli_support.hpp"
#include "hbtrack/analysis/adaptive_nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/case_system.hpp"
#include "test_support.hpp"

namespace hbtrack_tests::file_adaptive_harmonics {

using namespace hbtrack;
using Eigen::VectorXd;

// Dense harmonic-major coefficients of one dof, harmonics 0..H with magnitudes `m` (cosine part).
VectorXd one_dof(const std::vector<double>& m) {
  VectorXd x = VectorXd::Zero(static_cast<Eigen::Index>(2 * m.size() - 1));
  for (size_t k = 1; k < m.size(); ++k) x(static_cast<Eigen::Index>(2 * k - 1)) = m[k];
  return x;
}

TEST(AdaptiveHarmonics, TopShareReadsTheTopTwoHarmonicsAboveTheFirst) {
  // |X1| = 1, |X2| = 0, |X3| = 0.1: the top two of H = 3 are 2 and 3.
  const VectorXd x = one_dof({5.0, 1.0, 0.0, 0.1});
  EXPECT_NEAR(top_harmonic_share(x, 1, 3), 0.1 / std::sqrt(1.01), 1e-15);
  // Up to harmonic 2 only the zero harmonic 2 is on top (harmonic 1 is never counted).
  EXPECT_EQ(top_harmonic_share(x, 1, 2), 0.0);
  EXPECT_EQ(top_harmonic_share(VectorXd::Zero(7), 1, 3), 0.0);  // no response above the mean
  // Two dofs: the energies add over the dofs, harmonic by harmonic.
  VectorXd two = VectorXd::Zero(2 * 7);
  two(2 * 1) = 1.0;      // a1 of dof 0
  two(2 * 6 + 1) = 0.2;  // b3 of dof 1
  EXPECT_NEAR(top_harmonic_share(two, 2, 3), 0.2 / std::sqrt(1.04), 1e-15);
}

TEST(AdaptiveHarmonics, NextCountRisesDropsAndKeepsItsBand) {
  const AdaptiveHarmonics a{3, 6, 1e-3, 1e-6};
  // A top share above add_above asks for one more, below max.
  EXPECT_EQ(next_harmonic_count(a, one_dof({0, 1, 0, 1e-2, 0, 1e-2}), 1, 5), 6);
  EXPECT_EQ(next_harmonic_count(a, one_dof({0, 1, 0, 1e-2, 0, 1e-2, 1e-2}), 1, 6), 6);  // at max
  // Inside the band: H stays.
  EXPECT_EQ(next_harmonic_count(a, one_dof({0, 1, 0, 1e-2, 0, 1e-4}), 1, 5), 5);
  // A linear response drops to min at once.
  EXPECT_EQ(next_harmonic_count(a, one_dof({0, 1, 0, 0, 0, 0}), 1, 5), 3);
  // Top share below drop_below but the response truncated to H - 1 would be above the band's
  // middle sqrt(1e-9) = 3.2e-5 (harmonic 4 is 1e-4): H stays rather than chatter.
  EXPECT_EQ(next_harmonic_count(a, one_dof({0, 1, 0, 1e-7, 1e-4, 1e-7, 1e-7}), 1, 6), 6);
  // Harmonic 4 at 1e-5 is below the middle: down to 5 only (H = 5's top two hold harmonic 4).
  EXPECT_EQ(next_harmonic_count(a, one_dof({0, 1, 0, 1e-3, 1e-5, 1e-8, 1e-8}), 1, 6), 5);
}

TEST(AdaptiveHarmonics, PaddingAndTruncationKeepTheLowerHarmonics) {
  const VectorXd x = VectorXd::LinSpaced(2 * 5, 1.0, 10.0);  // q = 2, H = 2
  const VectorXd padded = with_harmonic_count(x, 2, 4);
  ASSERT_EQ(padded.size(), 2 * 9);
  EXPECT_EQ(padded.head(10), x);
  EXPECT_EQ(padded.tail(8), VectorXd::Zero(8));
  EXPECT_EQ(with_harmonic_count(padded, 2, 2), x);
}

// The systems an adaptive run visits, built once each.
struct Systems {
  explicit Systems(CaseDefinition c) : c_(std::move(c)) {}
  HarmonicBalance& operator()(int h) {
    auto found = built_.find(h);
    if (found == built_.end()) found = built_.emplace(h, runs::make_system_at(c_, h)).first;
    return found->second;
  }
  CaseDefinition c_;
  std::map<int, HarmonicBalance> built_;
};

NfrcResult adaptive_run(const CaseDefinition& c) {
  Systems systems(c);
  const AdaptiveStart start{c.harmonic_balance.harmonics, {}, c.nfrc.omega_start, {}};
  return compute_adaptive_nfrc(std::ref(systems), c.harmonic_balance.adaptive, start, c.nfrc, c.outputs);
}

NfrcResult fixed_run(const CaseDefinition& c, int harmonics) {
  HarmonicBalance hbm = runs::make_system_at(c, harmonics);
  return compute_nfrc(hbm, c.nfrc, c.outputs);
}

std::vector<double> limit_points(const NfrcResult& r) {
  std::vector<double> omegas;
  for (const SpecialPoint& p : r.continuation.special_points)
    if (p.type == SpecialPointType::limit_point) omegas.push_back(p.lambda);
  return omegas;
}

int harmonics_near(const NfrcResult& r, double omega) {
  size_t best = 0;
  for (size_t i = 0; i < r.recorded.size(); ++i)
    if (std::abs(r.recorded[i].omega - omega) < std::abs(r.recorded[best].omega - omega)) best = i;
  return r.recorded[best].balanced_harmonics;
}

const std::string kDuffing = test::source_path("examples/duffing.toml");
const std::string kContact = test::source_path("examples/two_dof_contact.toml");

// The two-dof contact: linear until the second mass reaches the stop near its resonance, then
// contact rich in harmonics. H sits at min off resonance and rises in contact.
TEST(AdaptiveHarmonics, RisesWhereTheContactActsAndDropsWhereTheResponseIsLinear) {
  const CaseDefinition c =
      load_case(kContact, {"harmonic_balance.harmonics=3", "harmonic_balance.adaptive={min=3, max=15, add_above=1e-3, drop_below=1e-5}",
                           "stability.method=\"none\""});
  const NfrcResult r = adaptive_run(c);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  int highest = 0;
  for (const RecordedPoint& p : r.recorded) highest = std::max(highest, p.balanced_harmonics);
  EXPECT_GE(highest, 10);                // contact: the top share stays above 1e-3 up to H = 10 at least
  EXPECT_EQ(harmonics_near(r, 0.3), 3);  // far below the first resonance (0.62): no contact
  EXPECT_EQ(harmonics_near(r, 2.0), 3);  // and far above the second (1.62)
  // Every point is padded to max, and its own H is recorded.
  for (size_t i = 0; i < r.recorded.size(); ++i) {
    EXPECT_EQ(r.continuation.points[i].u.size(), 31);  // the contact's dof retained, 2 max + 1 coefficients
    EXPECT_EQ(r.recorded[i].harmonic_numbers.size(), 16u);
  }
}

// Duffing: the limit points of the adaptive run against a fixed run at its max.
TEST(AdaptiveHarmonics, LimitPointsAgreeWithTheFixedRunAtMax) {
  const CaseDefinition c =
      load_case(kDuffing, {"harmonic_balance.harmonics=3", "harmonic_balance.adaptive={min=3, max=9, add_above=1e-4, drop_below=1e-7}"});
  const NfrcResult adaptive = adaptive_run(c), fixed = fixed_run(c, 9);
  const std::vector<double> a = limit_points(adaptive), f = limit_points(fixed);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(f.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    // The adaptive run's LP is balanced with the H it had there: its distance to the max-H LP
    // is the truncation of the harmonics above that H, which is no more than what dropping them
    // moves the fixed run's LP (the 1e-9 covers the two locations' own tolerance).
    const int h = harmonics_near(adaptive, a[i]);
    const double truncation = std::abs(limit_points(fixed_run(c, h))[i] - f[i]);
    EXPECT_LE(std::abs(a[i] - f[i]), truncation + 1e-9) << "LP " << i << " at H = " << h;
    EXPECT_LT(std::abs(a[i] - f[i]) / f[i], 1e-6) << "LP " << i << " at H = " << h;
  }
}

// However the thresholds place the junctions, each run finds the fixed run's two limit points
// once: a change of H that would move a fold across its junction waits.
TEST(AdaptiveHarmonics, NoJunctionLosesOrRepeatsALimitPoint) {
  for (const char* band : {"add_above=1e-2, drop_below=1e-4", "add_above=1e-3, drop_below=1e-6", "add_above=3e-5, drop_below=1e-8"}) {
    const CaseDefinition c =
        load_case(kDuffing, {"harmonic_balance.harmonics=5", std::string("harmonic_balance.adaptive={min=3, max=11, ") + band + "}",
                             "stability.method=\"none\""});
    const NfrcResult r = adaptive_run(c);
    int changes = 0;
    for (size_t i = 1; i < r.recorded.size(); ++i) changes += r.recorded[i].balanced_harmonics != r.recorded[i - 1].balanced_harmonics;
    EXPECT_GE(changes, 1) << band;
    EXPECT_EQ(limit_points(r).size(), 2u) << band;
  }
}

// One line naming the file, the field and the rule: the Duffing case with its [harmonic_balance]
// replaced by `settings`, written to a file of its own.
std::string error_of(const std::string& settings) {
  std::ifstream in(kDuffing);
  std::stringstream text;
  text << in.rdbuf();
  std::string body = text.str();
  const size_t at = body.find("harmonics = 7\n");
  body.replace(at, std::string("harmonics = 7\n").size(), settings + "\n");
  const std::string path = (test::fresh_temp_dir("adaptive_harmonics_bad", true) / "case.toml").string();
  std::ofstream(path) << body;
  try {
    load_case(path);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

TEST(AdaptiveHarmonics, BadSettingsFailNamingTheFieldAndTheRule) {
  const std::string h = "harmonics = 5\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {h + "adaptive = {min = 2, max = 9}", "harmonic_balance.adaptive.min: must be >= 3"},
      {h + "adaptive = {min = 6, max = 4}", "harmonic_balance.adaptive.max: must be >= min = 6"},
      {h + "adaptive = {min = 3, max = 9, drop_below = 0}", "harmonic_balance.adaptive.drop_below: must be > 0"},
      {h + "adaptive = {min = 3, max = 9, add_above = 1e-6, drop_below = 1e-5}",
       "harmonic_balance.adaptive.add_above: must be > drop_below"},
      {h + "adaptive = {min = 3, max = 9, add_above = 2}", "harmonic_balance.adaptive.add_above: must be < 1"},
      {h + "adaptive = {min = 3}", "harmonic_balance.adaptive.max: missing (required)"},
      {h + "adaptive = {min = 3, max = 9, add = 1}", "harmonic_balance.adaptive.add: unknown key"},
      {h + "adaptive = {min = 3, max = 40}", "harmonic_balance.samples: must be >= 2*adaptive.max+1 = 81, got 64"},
      {"harmonics = [1, 3, 5]\nadaptive = {min = 3, max = 9}", "harmonic_balance.adaptive: not with a list"},
      {h + "subharmonic = 2\nadaptive = {min = 3, max = 9}", "harmonic_balance.adaptive: not with subharmonic"},
      {"harmonics = 12\nadaptive = {min = 3, max = 9}",
       "harmonic_balance.harmonics: the H an adaptive run starts from must lie in [adaptive.min, adaptive.max] = [3, 9], got 12"},
  };
  for (const auto& [settings, rule] : cases) {
    const std::string e = error_of(settings);
    EXPECT_NE(e.find("case.toml:"), std::string::npos) << e;  // the file and its line
    EXPECT_NE(e.find(rule), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  // Every analysis but frc holds one H.
  const CaseDefinition c = load_case(kDuffing, {"harmonic_balance.adaptive={min=3, max=9}"});
  try {
    runs::make_system(c);
    ADD_FAILURE() << "an adaptive case's single system";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("harmonic_balance.adaptive: only frc changes H along a branch"), std::string::npos) << e.what();
  }
}

// The CLI: the harmonics column and summary, and one line refusing --resume and the verbs that
// hold one H.
TEST(AdaptiveHarmonics, CliWritesEachPointsHAndRefusesResumeAndOtherVerbs) {
  const auto dir = test::fresh_temp_dir("adaptive_harmonics_cli");
  const std::string sets = " --set harmonic_balance.harmonics=3 --set 'harmonic_balance.adaptive={min=3, max=9}'";
  const std::string out = (dir / "frc").string();
  ASSERT_EQ(test::run_cli("frc " + kDuffing + " -q -o " + out + sets).exit_code, 0);
  const nlohmann::json summary = test::read_json(dir / "frc" / "summary.json");
  EXPECT_EQ(summary.at("adaptive_harmonics").at("unknowns").at("min"), 7);     // 1 dof, H = 3
  EXPECT_EQ(summary.at("options").at("harmonic_balance").at("unknowns"), 19);  // the tables' H = max = 9
  std::ifstream branch(dir / "frc" / "branch.csv");
  std::string header;
  std::getline(branch, header);
  EXPECT_EQ(header.substr(header.rfind(',') + 1), "harmonics");
  EXPECT_NE(header.find(",h9_x,"), std::string::npos);
  const test::CliRun resume = test::run_cli("frc " + kDuffing + " -q --resume " + out + sets);
  EXPECT_EQ(resume.exit_code, 2);
  EXPECT_NE(resume.err.find("--resume: " + out + " is an adaptive-harmonics run"), std::string::npos) << resume.err;
  EXPECT_EQ(std::count(resume.err.begin(), resume.err.end(), '\n'), 1) << resume.err;
  const test::CliRun track = test::run_cli("track " + kDuffing + " --from " + out + " --lp 1 --param amplitude --range 0.5:1.5 -q -o " +
                                           (dir / "t").string() + sets);
  EXPECT_EQ(track.exit_code, 2);
  EXPECT_NE(track.err.find("harmonic_balance.adaptive: only frc changes H along a branch"), std::string::npos) << track.err;
}

}  // namespace hbtrack_tests::file_adaptive_harmonics
