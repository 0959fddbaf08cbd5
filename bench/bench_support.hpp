#pragma once
// Timing helpers shared by the benchmarks: costs are reported as ratios measured in one run.
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "hbtrack/util/dense_lu.hpp"
#include "hbtrack/util/phase_timer.hpp"

namespace hbtrack::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Median time of one dense partial-pivoting LU of a well-conditioned m x m matrix, by the
// library's backend (DenseLU) or, with `eigen`, by Eigen's PartialPivLU as built here.
inline double dense_lu_seconds(int m, bool eigen = false) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(m, m) + m * Eigen::MatrixXd::Identity(m, m);
  const int reps = std::max(5, static_cast<int>(2e7 / (static_cast<double>(m) * m * m)));
  std::vector<double> times;
  double sink = 0;
  DenseLU lu;
  Eigen::PartialPivLU<Eigen::MatrixXd> eigen_lu(m);
  for (int r = 0; r < std::min(reps, 2000); ++r) {
    const auto t0 = Clock::now();
    if (eigen)
      eigen_lu.compute(a);
    else
      lu.compute(a);
    times.push_back(seconds_since(t0));
    sink += eigen ? eigen_lu.matrixLU()(0, 0) : lu.log_abs_determinant();
  }
  if (sink == 42.0) std::printf(" ");  // keep the factorisations alive
  return median(times);
}

// Shares of a run's wall time spent in the library's timed phases (util/phase_timer.hpp),
// from PhaseTimes::reset() to now; "rest" is everything else (continuation logic, copies,
// the bordered matrix, condensation recovery, ...).
struct Breakdown {
  double aft = 0, jacobian = 0, factorization = 0, rest = 0;  // fractions of the wall time
  static Breakdown of(double wall) {
    Breakdown b;
    b.aft = PhaseTimes::seconds(Phase::aft) / wall;
    b.jacobian = PhaseTimes::seconds(Phase::jacobian) / wall;
    b.factorization = PhaseTimes::seconds(Phase::factorization) / wall;
    b.rest = 1.0 - b.aft - b.jacobian - b.factorization;
    return b;
  }
  std::string cells() const {
    char text[96];
    std::snprintf(text, sizeof text, "%.0f%% | %.0f%% | %.0f%% | %.0f%%", 100 * aft, 100 * jacobian, 100 * factorization, 100 * rest);
    return text;
  }
};

}  // namespace hbtrack::bench
