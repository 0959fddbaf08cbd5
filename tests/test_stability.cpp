// Stability: Hill's method against the monodromy matrix, and the stable/unstable segments of the
// Duffing example.
#include <gtest/gtest.h>

#include <algorithm>
#include <complex>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/stability/hill.hpp"
#include "hbtrack/stability/monodromy.hpp"
#include "test_support.hpp"

using namespace hbtrack;
using Eigen::VectorXd;

namespace {

std::vector<double> sorted_moduli(const Eigen::VectorXcd& mu) {
  std::vector<double> m;
  for (Eigen::Index i = 0; i < mu.size(); ++i) m.push_back(std::abs(mu(i)));
  std::sort(m.begin(), m.end());
  return m;
}

NfrcResult nfrc_of(const std::string& example, const std::vector<std::string>& sets, CaseDefinition& c,
                   std::unique_ptr<HarmonicBalance>& hbm) {
  c = load_case(test::source_path(example), sets);
  hbm = std::make_unique<HarmonicBalance>(c.model, c.elements, c.parameters, c.harmonic_balance);
  return compute_nfrc(*hbm, c.nfrc, c.outputs);
}

}  // namespace

TEST(Stability, HillAgreesWithMonodromyOnDuffing) {
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/duffing.toml", {"harmonic_balance.harmonics=11", "harmonic_balance.samples=128"}, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, "reached_end");
  int checked = 0;
  for (size_t i = 0; i < r.continuation.points.size(); i += 7) {
    const BranchPoint& p = r.continuation.points[i];
    const FloquetResult hill = hill_floquet(*hbm, p.u, p.lambda);
    const FloquetResult mono = monodromy_floquet(*hbm, p.u, p.lambda, 4000);
    const auto mh = sorted_moduli(hill.multipliers), mm = sorted_moduli(mono.multipliers);
    ASSERT_EQ(mh.size(), mm.size());
    // H = 11 resolves the Duffing response to ~1e-10 and RK4 with 4000 steps integrates to
    // ~1e-12: both are far below the 1e-6 asked of the agreement.
    for (size_t k = 0; k < mh.size(); ++k) EXPECT_NEAR(mh[k], mm[k], 1e-6 * mm[k]) << "point " << i << " omega " << p.lambda;
    EXPECT_EQ(hill.stable, mono.stable) << "point " << i;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}
