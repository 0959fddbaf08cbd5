#pragma once
// The progress of a study's running steps on the study's own status line. The steps are child
// processes whose stderr goes to their log, so they cannot draw on the terminal: each appends its
// progress to a file (--progress-file, progress.hpp) and this reads the last line of each a few
// times a second and shows them as one line, "study:   nfrc 37.5 % ~12s left": on a terminal
// rewritten in place, in a log (a pipe, a batch job) as a plain line at most every
// progress_line_interval_s() seconds between the steps' start and end lines.
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "progress.hpp"  // ProgressStyle

namespace hbtrack::cli {

// "nfrc 37.5 % ~12s left" ("point 42" without a range) from a step's progress file's last
// complete line; "" while the file has none.
std::string step_progress_text(const std::string& step, const std::string& file_text);

// The line a study prints when one of a stage's steps ends: "study:   validate_mu_9   exit 0,
// 9.6 s (step 21 of 36, stage ~1m20s left)". The estimate is the stage's pace so far (its steps
// end at ended / elapsed_s a second, whatever runs them in parallel) over the steps left; none
// before the first step or after the last.
std::string step_end_line(const std::string& step, int exit_code, double step_s, size_t ended, size_t steps, double stage_elapsed_s);

class StepProgressRelay {
 public:
  // Shows nothing (and watches no file) with ProgressStyle::none.
  explicit StepProgressRelay(ProgressStyle style);
  ~StepProgressRelay();  // clears the status line
  StepProgressRelay(const StepProgressRelay&) = delete;
  StepProgressRelay& operator=(const StepProgressRelay&) = delete;

  bool enabled() const { return enabled_; }
  // Step `step` reports to `file` (DIR/progress.txt); shown from its first line on.
  void watch(const std::string& step, const std::string& file);
  // The step ended: its last progress is drawn once (a step shorter than the poll shows too), its
  // file is removed and it leaves the line.
  void forget(const std::string& step);
  // A line of the study's own on stderr, below the status line (which is redrawn later).
  void say(const std::string& line);

 private:
  void loop();
  void clear_locked();
  void draw_locked(std::string line);  // the status line, replacing what is shown
  ProgressStyle style_;
  bool enabled_;
  std::chrono::steady_clock::time_point last_line_ = std::chrono::steady_clock::now();  // lines style
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::map<std::string, std::string> files_;  // step: its progress file
  size_t shown_ = 0;                          // characters of the status line on screen
  std::thread thread_;
};

}  // namespace hbtrack::cli
