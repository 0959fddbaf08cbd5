// Stability on a law that is not smooth, with default settings: Hill's method alone misjudges
// it there (slowly converging exponent families), so the monodromy cross-check decides, and the
// type of a PD/NS point is read from the multiplier on the unit circle.
#include <gtest/gtest.h>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

using namespace hbtrack;

namespace {

NfrcResult default_nfrc(const std::string& example, CaseDefinition& c, std::unique_ptr<HarmonicBalance>& hbm,
                        const std::vector<std::string>& sets = {}) {
  c = load_case(test::source_path(example), sets);
  hbm = std::make_unique<HarmonicBalance>(c.model, c.elements, c.parameters, c.harmonic_balance);
  return compute_nfrc(*hbm, c.nfrc, c.outputs);
}

}  // namespace

TEST(StabilityContact, TwoDofContactPeriodDoublesByDefault) {
  // Time integration from the HBM state at omega = 0.7646 grows into an exact period-2 motion.
  // The monodromy matrix puts the band's PD points at 0.7637 and 0.7691 (measured): the rows
  // between 0.7640 and 0.7689 are unstable (Hill alone called them stable).
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = default_nfrc("examples/two_dof_contact.toml", c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, "reached_end");
  int in_band = 0;
  for (const RecordedPoint& p : r.recorded) {
    if (p.omega < 0.7640 || p.omega > 0.7689) continue;
    ++in_band;
    EXPECT_EQ(p.stable, 0) << "omega " << p.omega;
    EXPECT_EQ(p.stability_method, "monodromy") << "omega " << p.omega;
  }
  EXPECT_GT(in_band, 0) << "no row in the band: the test checks nothing";
  int pd_in_band = 0;
  for (const SpecialPoint& sp : r.continuation.special_points)
    if (sp.type == "PD" && sp.lambda >= 0.763 && sp.lambda <= 0.770) {
      ++pd_in_band;
      EXPECT_EQ(sp.decided_by, "monodromy");
    }
  EXPECT_EQ(pd_in_band, 2) << "the band's two edges";
}

TEST(StabilityContact, CrossCheckOffLeavesHillAlone) {
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = default_nfrc("examples/two_dof_contact.toml", c, hbm, {"stability.cross_check=\"off\""});
  ASSERT_FALSE(r.recorded.empty());
  for (const RecordedPoint& p : r.recorded) EXPECT_EQ(p.stability_method, "hill");
}
