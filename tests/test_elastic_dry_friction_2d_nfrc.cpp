// examples/planar_jenkins.toml: two orthogonal oscillators held by a Jenkins slider in their
// plane, forced off-axis. Its harmonic-balance orbits against time integration of the equation
// of motion, and the convergence of the sampled friction law with the number of samples.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"
#include "time_integration_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_elastic_dry_friction_2d_nfrc {

using namespace hbtrack;
using Eigen::VectorXd;

namespace {

CaseDefinition example(int harmonics, int samples) {
  return load_case(test::source_path("examples/planar_jenkins.toml"),
                   {"harmonic_balance.harmonics=" + std::to_string(harmonics), "harmonic_balance.samples=" + std::to_string(samples)});
}

}  // namespace

TEST(PlanarJenkinsNfrc, HbmOrbitsAreTheTimeIntegratorsSteadyStates) {
  // The slider is stepped by the same return mapping in both (at the AFT's samples, at
  // Newmark's steps), whose discretisation error is O(1/N) (half a sample of lag, see
  // test_elastic_dry_friction_2d.cpp): with N = 2048 samples and 2048 steps per period both
  // solve the same sampled law, and what remains is the truncation to H = 21 harmonics of a
  // force with kinks and Newmark's O((2 pi / 2048)^2) ~ 1e-5. Measured with the CLI at N = steps:
  // 1.3e-4 at 1024, 3e-6 at 4096 (against 4e-4 to 2.5e-3 with N = 1024 and 4096 steps, the
  // O(1/N) of the law itself); so at 2048 the orbits must agree within 1e-4 of their range.
  // Newmark to the steady state at 2048 steps per period takes minutes under the sanitizers: the
  // Release pass runs it.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers: run by the Release pass";
  const int h = 21, samples = 2048;
  for (double omega : {0.97, 1.0, 1.2, 1.5}) {
    CaseDefinition c = example(h, samples);
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-11, 100);
    ASSERT_TRUE(s.converged) << "omega " << omega;
    const double worst = test::deviation_from_time_integration(c, hbm, s.x, omega, h, samples);
    std::printf("[ measured ] omega %.2f: largest deviation of Newmark's steady state from the HBM orbit %.2e of the range\n", omega,
                worst);
    EXPECT_LT(worst, 1e-4) << "omega " << omega;
  }
}

TEST(PlanarJenkinsNfrc, SampledLawConvergesAsOneOverTheSamples) {
  // The radial return lags the continuous slider by half a sample, so the solution moves by
  // O(1/N) as N grows: successive differences of the harmonics halve as N doubles (measured at
  // omega = 1.2: 4.95e-3, 2.48e-3, 1.24e-3 of their norm from 256 to 512, 1024, 2048; at 0.97,
  // 9.9e-4, 5.0e-4, 2.5e-4). Under the sanitizers (a minute) up to 1024 only.
  const std::vector<int> samples = test::kSanitizedBuild ? std::vector<int>{256, 512, 1024} : std::vector<int>{256, 512, 1024, 2048};
  const double omega = 1.2;
  std::vector<VectorXd> solutions;
  for (int n : samples) {
    CaseDefinition c = example(7, n);
    HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    const FixedFrequencySolution s = solve_at_frequency(hbm, omega, c.outputs, 1e-12, 100);
    ASSERT_TRUE(s.converged) << "N " << n;
    solutions.push_back(s.x);
  }
  std::vector<double> change;
  for (size_t i = 1; i < solutions.size(); ++i) {
    change.push_back((solutions[i] - solutions[i - 1]).norm() / solutions.back().norm());
    std::printf("[ measured ] omega %.2f: relative change of the harmonics from N = %d to %d: %.2e\n", omega, samples[i - 1], samples[i],
                change.back());
  }
  for (size_t i = 1; i < change.size(); ++i) {
    EXPECT_GT(change[i - 1] / change[i], 1.6) << "N " << samples[i];
    EXPECT_LT(change[i - 1] / change[i], 2.5) << "N " << samples[i];
  }
}

}  // namespace hbtrack_tests::file_elastic_dry_friction_2d_nfrc
