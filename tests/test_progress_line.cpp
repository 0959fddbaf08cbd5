// The progress line of frc and track (apps/hbtrack/progress.hpp): the fraction of the range
// covered, its text, and the plain lines at a bounded rate when stderr is not a terminal; the
// lines a step relays to the study's line (step_progress.hpp). (On a terminal, frc's and
// track's lines are read through a pseudo-terminal in python/tests/test_progress.py.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"
#include "progress.hpp"
#include "step_progress.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_progress_line {

namespace fs = std::filesystem;
using hbtrack::cli::Coverage;
using hbtrack::cli::covered_fraction;
using hbtrack::cli::parse_relay_line;
using hbtrack::cli::progress_text;
using hbtrack::cli::ProgressState;
using hbtrack::cli::relay_line;
using hbtrack::cli::step_end_line;
using hbtrack::cli::step_progress_text;
using hbtrack::test::CliRun;
using hbtrack::test::run_cli;

TEST(ProgressLine, OneWayCoverageKeepsTheFurthestValueInEitherDirection) {
  Coverage up = Coverage::one_way(0.5, 1.5);
  EXPECT_DOUBLE_EQ(up.add(0.75), 0.25);
  EXPECT_DOUBLE_EQ(up.add(1.0), 0.5);
  EXPECT_DOUBLE_EQ(up.add(0.9), 0.5) << "a branch folding back does not lower it";
  EXPECT_DOUBLE_EQ(up.add(NAN), 0.5);
  EXPECT_DOUBLE_EQ(up.add(2.0), 1.0);
  Coverage down = Coverage::one_way(2.0, 1.0);
  EXPECT_DOUBLE_EQ(down.add(1.5), 0.5);
}

TEST(ProgressLine, TrackingCoverageCountsEachLegForItsShareOfTheRange) {
  // A limit point at 1.7 followed in [0.2, 2.2] (width 2): leg 1 down towards 0.2 (3/4 of the
  // range), leg 2 up towards 2.2 (the last quarter). Within a leg: the part r of its way reached,
  // plus the distance T travelled, r + (1 - r) T / (T + 2).
  const auto way = [](double r, double travelled) { return r + (1 - r) * travelled / (travelled + 2); };
  Coverage c = Coverage::two_legs(0.2, 2.2, 1.7);
  EXPECT_DOUBLE_EQ(c.fraction(), 0.0);
  EXPECT_DOUBLE_EQ(c.add(1.2, 1), 0.75 * way(1.0 / 3, 0.5));
  EXPECT_DOUBLE_EQ(c.add(0.7, 1), 0.75 * way(2.0 / 3, 1.0));
  // At a cusp leg 1 turns back up and leaves the range at 2.2: the distance travelled still
  // moves the share, and leg 1 counts as whole once leg 2 starts.
  EXPECT_DOUBLE_EQ(c.add(1.5, 1), 0.75 * way(2.0 / 3, 1.8));
  EXPECT_DOUBLE_EQ(c.add(2.2, 1), 0.75 * way(2.0 / 3, 2.5));
  EXPECT_DOUBLE_EQ(c.add(1.7, 2), 0.75);
  EXPECT_DOUBLE_EQ(c.add(1.95, 2), 0.75 + 0.25 * way(0.5, 0.25));
  EXPECT_DOUBLE_EQ(c.add(NAN, 2), 0.75 + 0.25 * way(0.5, 0.25));
  EXPECT_DOUBLE_EQ(c.add(3.0, 2), 1.0) << "clamped to the range";
  // A limit point at the range's end: all of it is leg 2's.
  Coverage at_end = Coverage::two_legs(0.0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(at_end.add(0.0, 1), 0.0);
  EXPECT_DOUBLE_EQ(at_end.add(0.5, 2), 0.5 + 0.5 * 0.5 / 1.5);
}

TEST(ProgressLine, TrackingCoverageMovesOnEveryPointOfALegThatWanders) {
  // The absorber's first leg (examples/nltva.toml, LP 1 in [0.01, 0.4] from 0.12): down to a
  // minimum at 0.096, then back up past the start and out of the range at 0.4. Before, the share
  // sat at its value at the minimum for the 45 points after it.
  Coverage c = Coverage::two_legs(0.01, 0.4, 0.12);
  double before = c.add(0.12, 1);
  for (const double a : {0.11, 0.1, 0.096, 0.1, 0.12, 0.15, 0.18, 0.184, 0.17, 0.13, 0.125, 0.16, 0.23, 0.33, 0.4}) {
    const double now = c.add(a, 1);
    EXPECT_GT(now, before) << "at amplitude " << a;
    before = now;
  }
  EXPECT_LT(before, covered_fraction(0.12, 0.01, 0.4)) << "within leg 1's share";
}

TEST(ProgressLine, TextShowsTheParameterThePercentageAndTheTimeLeft) {
  ProgressState s;
  s.index = 42;
  s.omega = 1.25;
  s.parameter = "amplitude";
  s.parameter_value = 0.8;
  s.fraction = 0.25;
  s.elapsed_s = 10;
  s.output = "x";
  s.output_max = 2.5;
  const std::string line = progress_text(s);
  EXPECT_NE(line.find("point    42"), std::string::npos) << line;
  EXPECT_NE(line.find("omega 1.25"), std::string::npos) << line;
  EXPECT_NE(line.find("amplitude 0.8"), std::string::npos) << line;
  EXPECT_NE(line.find(" 25.0 %"), std::string::npos) << line;
  EXPECT_NE(line.find("~30s left"), std::string::npos) << "10 s for a quarter: 30 s for the rest: " << line;
  EXPECT_NE(line.find("max_x 2.5"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << "one line, rewritten in place";

  s.fraction = 1;  // done: no estimate
  EXPECT_EQ(progress_text(s).find("left"), std::string::npos);
  s.parameter.clear();  // frc: no parameter, no range
  s.fraction = -1;
  EXPECT_EQ(progress_text(s).find('%'), std::string::npos);
  EXPECT_EQ(progress_text(s).find("amplitude"), std::string::npos);
}

TEST(ProgressLine, ARunShorterThanTheIntervalWritesNoProgressLineInALog) {
  unsetenv("HBTRACK_PROGRESS_INTERVAL");  // the default, 5 s
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_progress_track_" + std::to_string(getpid()));
  fs::remove_all(dir);
  // Duffing at 3 harmonics: an NFRC over the resonance and the tracking curve in 0.1 s.
  std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  duffing += " --set harmonic_balance.harmonics=3";
  const CliRun frc =
      run_cli("frc " + duffing + " --set continuation.omega_start=1.0 --set continuation.omega_end=1.4 -q -o " + (dir / "frc").string());
  ASSERT_EQ(frc.exit_code, 0) << frc.err;
  // stderr is a file here, as in a log or a batch job; the run takes a tenth of a second.
  const CliRun track = run_cli("track " + duffing + " --from " + (dir / "frc").string() + " --lp 1 --param amplitude --range 0.5:1.5 -o " +
                               (dir / "track").string());
  ASSERT_EQ(track.exit_code, 0) << track.err;
  EXPECT_EQ(track.err.find('\r'), std::string::npos) << track.err;
  EXPECT_EQ(track.err.find('%'), std::string::npos) << track.err;
  EXPECT_NE(track.err.find("track: "), std::string::npos) << "the closing report still comes: " << track.err;
  fs::remove_all(dir);
}

TEST(ProgressLine, RelayLinesReadBackAndAPartLineIsRefused) {
  ProgressState s;
  s.index = 42;
  s.fraction = 0.375;
  s.elapsed_s = 12.5;
  ProgressState back;
  ASSERT_TRUE(parse_relay_line(relay_line(s), back)) << relay_line(s);
  EXPECT_EQ(back.index, 42);
  EXPECT_DOUBLE_EQ(back.fraction, 0.375);
  EXPECT_DOUBLE_EQ(back.elapsed_s, 12.5);
  EXPECT_FALSE(parse_relay_line("42 0.37", back)) << "a line cut short by a writer";
  EXPECT_FALSE(parse_relay_line("42 0.375 12.5 extra", back));
  EXPECT_FALSE(parse_relay_line("point 42", back));
}

TEST(ProgressLine, StudyShowsEachStepsLastCompleteLine) {
  ProgressState s;
  s.index = 7;
  s.fraction = 0.25;
  s.elapsed_s = 10;
  const std::string first = relay_line(s);
  s.index = 9;
  s.fraction = 0.5;
  const std::string second = relay_line(s);
  // The writer is half-way through a third line: the second is the last complete one.
  EXPECT_EQ(step_progress_text("nfrc", first + second + "11 0.7"), "nfrc 50.0 % ~10s left");
  EXPECT_EQ(step_progress_text("nfrc", first), "nfrc 25.0 % ~30s left") << "10 s for a quarter: 30 s for the rest";
  EXPECT_EQ(step_progress_text("nfrc", ""), "") << "a step that has not reported yet";
  EXPECT_EQ(step_progress_text("nfrc", "11 0.7"), "");
  s.fraction = -1;  // a backbone: no range
  EXPECT_EQ(step_progress_text("backbone_mode1", relay_line(s)), "backbone_mode1 point 9");
}

TEST(ProgressLine, StudyStepEndLinesEstimateWhatIsLeftOfTheStage) {
  // 9 of 36 steps ended in 30 s (whatever ran them in parallel): 27 left at that pace is 90 s.
  EXPECT_EQ(step_end_line("validate_mu_9", 0, 9.6, 9, 36, 30.0),
            "study:   validate_mu_9              exit 0, 9.6 s (step 9 of 36, stage ~1m30s left)");
  // The last step: nothing is left to estimate; a stage of one step never has an estimate.
  EXPECT_EQ(step_end_line("nfrc", 0, 20.0, 1, 1, 20.0), "study:   nfrc                       exit 0, 20.0 s (step 1 of 1)");
  EXPECT_EQ(step_end_line("validate_mu_36", 1, 9.6, 36, 36, 120.0).find("left"), std::string::npos);
}

namespace {

// The percentages of the plain progress lines in a log, in order; false in `plain` when a line
// is rewritten in place (a carriage return).
std::vector<double> logged_percentages(const std::string& err) {
  std::vector<double> percentages;
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    const size_t percent = line.find(" %");
    if (line.rfind("point", 0) != 0 || percent == std::string::npos) continue;
    percentages.push_back(std::stod(line.substr(line.rfind(' ', percent - 1) + 1)));
  }
  return percentages;
}

// The longest run of equal consecutive values.
size_t longest_stall(const std::vector<double>& values) {
  size_t longest = 0, run = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    run = i > 0 && values[i] == values[i - 1] ? run + 1 : 1;
    longest = std::max(longest, run);
  }
  return longest;
}

}  // namespace

TEST(ProgressLine, FrcWritesPlainLinesInALogAtTheIntervalAndEndsAtAHundredPercent) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_progress_log");
  // Duffing at a tenth of its step: about 800 points in half a second, a line every 20 ms.
  setenv("HBTRACK_PROGRESS_INTERVAL", "0.02", 1);
  const CliRun frc = run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") +
                             " --set continuation.step=0.01 --set continuation.step_max=0.01 -o " + dir.string());
  unsetenv("HBTRACK_PROGRESS_INTERVAL");
  ASSERT_EQ(frc.exit_code, 0) << frc.err;
  EXPECT_EQ(frc.err.find('\r'), std::string::npos) << "plain lines in a log: " << frc.err;
  const std::vector<double> percentages = logged_percentages(frc.err);
  ASSERT_GE(percentages.size(), 3u) << frc.err;
  EXPECT_TRUE(std::is_sorted(percentages.begin(), percentages.end())) << frc.err;
  EXPECT_EQ(percentages.back(), 100.0) << "the last state once more at the end: " << frc.err;
  // Bounded: at most a line per interval (the run's length over 20 ms), and the last one.
  const double wall_s = nlohmann::json::parse(std::ifstream(dir / "summary.json"))["timings"]["wall_s"];
  EXPECT_LE(percentages.size(), static_cast<size_t>(wall_s / 0.02) + 2) << frc.err;
  EXPECT_LT(frc.err.find("point"), frc.err.find("frc: ")) << "the closing report comes last: " << frc.err;
  fs::remove_all(dir);
}

TEST(ProgressLine, TrackShareMovesOnEveryLegInALog) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_progress_track_log");
  const std::string nltva = hbtrack::test::source_path("examples/nltva.toml");
  ASSERT_EQ(run_cli("frc " + nltva + " -q -o " + (dir / "frc").string()).exit_code, 0);
  // A line per point: the absorber's LP 1, whose first leg turns at a minimum and leaves the
  // range at its other end (75 points; the share sat at 6.7 % for 50 of them).
  setenv("HBTRACK_PROGRESS_INTERVAL", "1e-9", 1);
  const CliRun track = run_cli("track " + nltva + " --from " + (dir / "frc").string() + " --lp 1 --param amplitude --range 0.01:0.4 -o " +
                               (dir / "track").string());
  unsetenv("HBTRACK_PROGRESS_INTERVAL");
  ASSERT_EQ(track.exit_code, 0) << track.err;
  const std::vector<double> percentages = logged_percentages(track.err);
  ASSERT_GE(percentages.size(), 50u) << track.err;
  EXPECT_TRUE(std::is_sorted(percentages.begin(), percentages.end())) << track.err;
  EXPECT_EQ(percentages.back(), 100.0) << track.err;
  EXPECT_LE(longest_stall(percentages), 6u) << track.err;
  fs::remove_all(dir);
}

}  // namespace hbtrack_tests::file_progress_line
