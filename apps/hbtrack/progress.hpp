#pragma once
// The progress report of a running verb on stderr: the point, omega, the tracked parameter's
// value, the first output's maximum and, when the verb knows the range it covers, the percentage
// covered and the time left at the pace so far. On a terminal one line rewritten per point; when
// stderr is not a terminal (a log, a pipe, a batch job) a plain line at most every
// progress_line_interval_s() seconds, and the last state once more at the end if any was
// written (a run shorter than the interval writes none); nothing with -q. A --progress-file gets
// the updates as lines whatever stderr is: `hbtrack study` shows its steps' progress from them
// (step_progress.hpp).
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/util/coverage.hpp"

namespace hbtrack::cli {

// "42s", "3m07s", "1h05m".
std::string duration_text(double seconds);

// The coverage of a run's range is the library's, shared with the Python module's callbacks.
using hbtrack::Coverage;
using hbtrack::covered_fraction;

// What one update of the line shows.
struct ProgressState {
  int index = 0;
  double omega = 0;
  std::string parameter;  // the tracked parameter ("" for none) and its value
  double parameter_value = 0;
  double fraction = -1;  // of the range covered; negative when the run has no range
  double elapsed_s = 0;  // since the start, for the time left
  std::string output;    // the first output's name ("" for none) and its maximum
  double output_max = 0;
};

// The line's text (without the '\r' that returns to its start), padded so that a shorter update
// overwrites a longer one: "  point    42  omega 1.25  amplitude 0.8  37.5 %  ~12s left ...".
std::string progress_text(const ProgressState& s);

// "~12s left" at the pace so far; "" when too little (under 1 %) or all is done.
std::string time_left_text(double fraction, double elapsed_s);

// One update as a line of a --progress-file, "INDEX FRACTION ELAPSED_S" (fraction -1 without a
// range), and read back: false for a line that is not one (a partly written last line).
std::string relay_line(const ProgressState& s);
bool parse_relay_line(const std::string& line, ProgressState& s);

// Seconds between two progress lines when stderr is not a terminal: 5, or the environment's
// HBTRACK_PROGRESS_INTERVAL (a positive number; the tests use a short one).
double progress_line_interval_s();

// How the updates reach stderr.
enum class ProgressStyle { none, terminal, lines };
// none with -q, terminal when stderr is one, lines otherwise.
ProgressStyle progress_style(bool quiet);

class Progress {
 public:
  explicit Progress(bool quiet);
  // A run over [range_start, range_end] of omega (frc): the report adds the percentage covered
  // and the time left.
  Progress(bool quiet, double range_start, double range_end);
  // A limit point followed in `parameter` from `from` inside [lo, hi], in two legs (track): the
  // report adds the parameter's value, the percentage covered and the time left.
  Progress(bool quiet, const std::string& parameter, double lo, double hi, double from);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(int index, double omega, const RecordedPoint& p, const std::vector<OutputDof>& outputs);
  // A tracking point of `leg` (1 or 2): `parameter_value` is where it is in the range.
  void update(int index, double omega, double parameter_value, int leg, const RecordedPoint& p, const std::vector<OutputDof>& outputs);
  // Ends the line, once: the warnings and the closing report that follow start on their own line.
  void finish();
  // Also appends the updates to `path` as relay_line()s, terminal or not, quiet or not (for a
  // parent process: hbtrack study); "" for none. Throws CaseError when it cannot be opened.
  void relay_to(const std::string& path);

 private:
  void show(ProgressState s, double position, int leg, const RecordedPoint& p, const std::vector<OutputDof>& outputs);
  void write_line(const std::string& text);
  ProgressStyle style_;
  bool has_range_ = false, shown_ = false;
  // Lines style: when the last line was written, how many were, and the latest update not
  // written yet (written by finish(), so that a log ends with where the run stopped).
  std::chrono::steady_clock::time_point last_line_{};
  int lines_written_ = 0;
  std::string unwritten_;
  std::FILE* relay_ = nullptr;
  std::chrono::steady_clock::time_point last_relayed_{};
  Coverage coverage_;
  std::string parameter_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

}  // namespace hbtrack::cli
