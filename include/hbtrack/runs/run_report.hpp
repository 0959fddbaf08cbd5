#pragma once
// What every run returns (as Ceres' Solver::Summary): the summary it wrote last, and one line for
// the caller to show.
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>

namespace hbtrack::runs {

struct RunReport {
  nlohmann::json summary{};
  // "" when the run reached its end; else what stopped it, after how many points and where they
  // are kept (the command line exits 1 with this line, Python leaves it to the summary).
  std::string failure{};
  // A finished run in one line: "120 points, 2 special points, 431 Newton iterations, 0.412 s".
  std::string brief{};
  bool success() const { return failure.empty(); }
};

// The summaries' timings: wall-clock seconds since t0.
using RunClock = std::chrono::steady_clock;
inline double seconds_since(RunClock::time_point t0) { return std::chrono::duration<double>(RunClock::now() - t0).count(); }

}  // namespace hbtrack::runs
