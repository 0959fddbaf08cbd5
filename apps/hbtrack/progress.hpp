#pragma once
// The one-line progress report of a running verb on a terminal (stderr): the point, omega, the
// first output's maximum and, when the verb knows the range it covers, the percentage covered
// and the time left at the pace so far. Silent when stderr is not a terminal (a log, a pipe, a
// batch job) or with -q.
#include <chrono>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"

namespace hbtrack::cli {

// "42s", "3m07s", "1h05m".
std::string duration_text(double seconds);

// The part of [start, end] that `value` has covered, 0 to 1 (either direction; 0 for an empty
// range or a value that is not finite).
double covered_fraction(double value, double start, double end);

class Progress {
 public:
  explicit Progress(bool quiet);
  // A run over [range_start, range_end] of omega: the report adds the percentage covered (the
  // furthest so far: a folding branch that steps back does not lower it) and the time left.
  Progress(bool quiet, double range_start, double range_end);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(int index, double omega, const RecordedPoint& p, const std::vector<OutputDof>& outputs);

 private:
  bool enabled_, has_range_ = false;
  double start_ = 0, end_ = 0, furthest_ = 0;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

}  // namespace hbtrack::cli
