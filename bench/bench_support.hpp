#pragma once
// Timing helpers shared by the benchmarks: costs are reported as ratios measured in one run.
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace hbtrack::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Median time of one dense partial-pivoting LU of a well-conditioned m x m matrix.
inline double dense_lu_seconds(int m) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(m, m) + m * Eigen::MatrixXd::Identity(m, m);
  const int reps = std::max(5, static_cast<int>(2e7 / (static_cast<double>(m) * m * m)));
  std::vector<double> times;
  double sink = 0;
  for (int r = 0; r < std::min(reps, 2000); ++r) {
    const auto t0 = Clock::now();
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
    times.push_back(seconds_since(t0));
    sink += lu.matrixLU()(0, 0);
  }
  if (sink == 42.0) std::printf(" ");  // keep the factorisations alive
  return median(times);
}

}  // namespace hbtrack::bench
