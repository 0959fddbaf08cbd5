// The tracking checkpoint (results/continuation_state_file.hpp) keeps each finished leg's stop
// reason by its name, reads it back as the same enum, and reports a name it does not know as bad
// input naming the file and the field (a hand-edited or foreign file), never as a crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "hbtrack/results/continuation_state_file.hpp"
#include "hbtrack/results/results_writer.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_tracking_checkpoint {

using namespace hbtrack;
namespace fs = std::filesystem;

// The smallest state read_tracking_state accepts: leg 2 under way after one finished leg, its
// engine one point in (x = [u; lambda] of a single unknown).
FoldTrackingState second_leg_state(StopReason first_leg) {
  FoldTrackingState s;
  s.leg = 2;
  s.curve_points = 1;
  s.continuation.points = 1;
  s.continuation.x = Eigen::Vector2d(0.5, 1.0);
  s.continuation.x_before = s.continuation.x;
  s.continuation.tangent = Eigen::Vector2d(0.0, 1.0);
  s.continuation.unknown_scale = Eigen::VectorXd::Ones(1);
  s.continuation.first = {Eigen::VectorXd::Zero(1), 1.0, Eigen::Vector2d(0.0, 1.0), 0, 0.0};
  s.continuation.first_scale = Eigen::VectorXd::Ones(1);
  s.lambda_slopes = {1.0};
  ContinuationSummary leg;
  leg.stop_reason = first_leg;
  leg.points = 7;
  s.finished_legs = {leg};
  return s;
}

class TrackingCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hbtrack_tracking_checkpoint_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path() const { return (dir_ / "checkpoint.json").string(); }
  fs::path dir_;
};

TEST_F(TrackingCheckpoint, AFinishedLegKeepsItsStopReason) {
  for (StopReason reason : {StopReason::left_range, StopReason::max_points, StopReason::step_size_underflow}) {
    write_tracking_state(path(), second_leg_state(reason), nlohmann::json::object());
    std::ifstream in(path());
    const nlohmann::json written = nlohmann::json::parse(in);
    // The file holds the name, as summary.json does, not the enum's number.
    EXPECT_EQ(written["tracking"]["finished_legs"][0]["stop_reason"], to_string(reason));
    const SavedTracking saved = read_tracking_state(path());
    ASSERT_EQ(saved.state.finished_legs.size(), 1u);
    EXPECT_EQ(saved.state.finished_legs[0].stop_reason, reason);
    EXPECT_EQ(saved.state.finished_legs[0].points, 7);
  }
}

TEST_F(TrackingCheckpoint, AnUnknownStopReasonIsBadInputNamingTheFileAndField) {
  write_tracking_state(path(), second_leg_state(StopReason::reached_end), nlohmann::json::object());
  nlohmann::json document;
  {
    std::ifstream in(path());
    document = nlohmann::json::parse(in);
  }
  document["tracking"]["finished_legs"][0]["stop_reason"] = "reached_the_end";
  write_json_atomically(path(), document);
  try {
    read_tracking_state(path());
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path() + ": tracking.finished_legs[0].stop_reason: must be running, reached_end, ", 0), 0u) << message;
    EXPECT_NE(message.find(", got 'reached_the_end'"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

}  // namespace hbtrack_tests::file_tracking_checkpoint
