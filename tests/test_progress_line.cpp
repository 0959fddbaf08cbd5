// The progress line of frc and track (apps/hbtrack/progress.hpp): the fraction of the range
// covered, its text, and its silence when stderr is not a terminal; the lines a step relays to
// the study's line (step_progress.hpp). (On a terminal, frc's and
// track's lines are read through a pseudo-terminal in python/tests/test_progress.py.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "cli_support.hpp"
#include "progress.hpp"
#include "step_progress.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using hbtrack::cli::Coverage;
using hbtrack::cli::parse_relay_line;
using hbtrack::cli::relay_line;
using hbtrack::cli::step_progress_text;
using hbtrack::cli::progress_text;
using hbtrack::cli::ProgressState;
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
  // A limit point at 1.7 followed in [0.2, 2.2]: leg 1 down towards 0.2 (3/4 of the range), leg 2
  // up towards 2.2 (the last quarter).
  Coverage c = Coverage::two_legs(0.2, 2.2, 1.7);
  EXPECT_DOUBLE_EQ(c.fraction(), 0.0);
  EXPECT_DOUBLE_EQ(c.add(1.2, 1), 0.25);
  EXPECT_DOUBLE_EQ(c.add(0.7, 1), 0.5);
  // At a cusp leg 1 turns back up and leaves the range at 2.2: no progress until leg 2 starts,
  // then leg 1 counts as whole.
  EXPECT_DOUBLE_EQ(c.add(1.5, 1), 0.5);
  EXPECT_DOUBLE_EQ(c.add(2.2, 1), 0.5);
  EXPECT_DOUBLE_EQ(c.add(1.7, 2), 0.75);
  EXPECT_DOUBLE_EQ(c.add(1.95, 2), 0.875);
  EXPECT_DOUBLE_EQ(c.add(NAN, 2), 0.875);
  EXPECT_DOUBLE_EQ(c.add(3.0, 2), 1.0) << "clamped to the range";
  // A limit point at the range's end: all of it is leg 2's.
  Coverage at_end = Coverage::two_legs(0.0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(at_end.add(0.0, 1), 0.0);
  EXPECT_DOUBLE_EQ(at_end.add(0.5, 2), 0.5);
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

TEST(ProgressLine, TrackWritesNoProgressLineWhenStderrIsNotATerminal) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_progress_track_" + std::to_string(getpid()));
  fs::remove_all(dir);
  // Duffing at 3 harmonics: an NFRC over the resonance and the tracking curve in 0.1 s.
  std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  duffing += " --set harmonic_balance.harmonics=3";
  const CliRun frc =
      run_cli("frc " + duffing + " --set continuation.omega_start=1.0 --set continuation.omega_end=1.4 -q -o " + (dir / "frc").string());
  ASSERT_EQ(frc.exit_code, 0) << frc.err;
  // stderr is a file here, as in a log or a batch job.
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
