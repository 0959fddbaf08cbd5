// An output's time signal (dof_signal, behind every point's max/min columns) is its harmonics'
// sum at the period's samples: equal to the direct sum of cosines and sines to round-off, for
// any number of samples, harmonics beyond the Nyquist limit included (the table it reads wraps
// j i modulo the samples), and from one call to the next with another sample count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbtrack/hbm/recorded_outputs.hpp"

namespace hbtrack_tests::file_recorded_outputs {

using namespace hbtrack;

namespace {

double direct_sum(const Eigen::VectorXd& full, int dofs, int harmonics, int dof, double tau) {
  double v = 0.5 * full(dof);
  for (int j = 1; j <= harmonics; ++j)
    v += full((2 * j - 1) * dofs + dof) * std::cos(j * tau) + full(2 * j * dofs + dof) * std::sin(j * tau);
  return v;
}

}  // namespace

TEST(RecordedOutputs, DofSignalIsTheDirectSumOfItsHarmonics) {
  const int dofs = 3, dof = 1;
  for (const int harmonics : {1, 5, 21}) {
    // 7 samples are fewer than 2 H + 1 at H = 5 and 21: j i wraps many times.
    for (const int samples : {1024, 7, 64, 1024}) {
      Eigen::VectorXd full = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs) * (2 * harmonics + 1));
      for (Eigen::Index k = 0; k < full.size(); ++k) full(k) = std::sin(1.7 * static_cast<double>(k) + 0.3);
      const Eigen::VectorXd x = dof_signal(full, dofs, harmonics, dof, samples);
      ASSERT_EQ(x.size(), samples);
      // Each term is at most 1 in size: 2 H + 1 terms of round-off 1e-16 each, and the argument's
      // reduction (j tau against the sample j i mod N) another few 1e-16 per term.
      for (int i = 0; i < samples; ++i)
        EXPECT_NEAR(x(i), direct_sum(full, dofs, harmonics, dof, 2.0 * std::numbers::pi * i / samples), 1e-13 * harmonics)
            << "H " << harmonics << ", N " << samples << ", sample " << i;
    }
  }
}

}  // namespace hbtrack_tests::file_recorded_outputs
