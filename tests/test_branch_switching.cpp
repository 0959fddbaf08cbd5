// Branch switching at a symmetry-breaking branch point (`hbtrack switch`): on the coupled
// Duffing oscillators the new branch is asymmetric and meets the symmetric one at the BP.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "hbtrack/analysis/branch_switching.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_branch_switching {

using namespace hbtrack;
using Eigen::VectorXd;
namespace fs = std::filesystem;

TEST(BranchSwitching, CoupledDuffingBranchIsAsymmetricAndMeetsTheSymmetricOneAtTheBranchPoint) {
  const CaseDefinition c = load_case(test::source_path("examples/coupled_duffing.toml"));
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  const NfrcResult nfrc = compute_nfrc(hbm, c.nfrc, c.outputs);
  ASSERT_EQ(nfrc.continuation.summary.stop_reason, StopReason::reached_end);
  const SpecialPoint* bp = nullptr;
  for (const SpecialPoint& sp : nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::branch_point && sp.located) {
      bp = &sp;
      break;
    }
  ASSERT_NE(bp, nullptr);
  const auto& points = nfrc.continuation.points;
  const size_t i = static_cast<size_t>(bp->index);
  ASSERT_TRUE(i > 0 && i + 1 < points.size());
  VectorXd known(hbm.unknowns() + 1);
  known.head(hbm.unknowns()) = points[i + 1].u - points[i - 1].u;
  known(hbm.unknowns()) = points[i + 1].lambda - points[i - 1].lambda;
  const SwitchedBranch s = switch_at_branch_point(hbm, c.nfrc, c.outputs, bp->u, bp->lambda, known);
  ASSERT_TRUE(s.away.continuation.success()) << s.away.continuation.summary.stop_reason;
  ASSERT_TRUE(s.through.continuation.success()) << s.through.continuation.summary.stop_reason;

  // Asymmetric: the harmonics of x1 and x2 (retained dofs 0 and 1 of each harmonic) differ by
  // a large fraction of the motion along the new branch, while they agree on the symmetric one.
  double asymmetry = 0;
  for (const auto* leg : {&s.away, &s.through})
    for (const BranchPoint& p : leg->continuation.points) {
      const Eigen::Map<const Eigen::MatrixXd> h(p.u.data(), 2, p.u.size() / 2);
      asymmetry = std::max(asymmetry, (h.row(0) - h.row(1)).norm() / h.norm());
    }
  EXPECT_GT(asymmetry, 0.3);
  const Eigen::Map<const Eigen::MatrixXd> hb(bp->u.data(), 2, bp->u.size() / 2);
  EXPECT_LT((hb.row(0) - hb.row(1)).norm(), 1e-8 * hb.norm());

  // The leg back through the BP turns there in omega (a pitchfork: omega - omega_bp ~ e^2 on
  // the new branch, x - x_bp ~ e): its located LP is the BP. In omega to 1e-6 relative (both
  // located by secants on Newton-converged branches; a step is 1e-2). In the state only to the
  // square root of that accuracy (e ~ sqrt(d omega)): 1e-3 relative, still 300 times below the
  // branch's asymmetry above (measured: 5e-5).
  const SpecialPoint* meet = nullptr;
  for (const SpecialPoint& sp : s.through.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point && sp.located &&
        (!meet || std::abs(sp.lambda - bp->lambda) < std::abs(meet->lambda - bp->lambda)))
      meet = &sp;
  ASSERT_NE(meet, nullptr);
  EXPECT_NEAR(meet->lambda, bp->lambda, 1e-6 * bp->lambda);
  EXPECT_LT((meet->u - bp->u).cwiseAbs().maxCoeff(), 1e-3 * bp->u.cwiseAbs().maxCoeff());
}

TEST(SwitchCli, FollowsTheNewBranchAndRejectsAPointThatIsNoBranchPoint) {
  const fs::path frc = fs::temp_directory_path() / ("hbtrack_switch_frc_" + std::to_string(getpid()));
  const fs::path out = fs::temp_directory_path() / ("hbtrack_switch_" + std::to_string(getpid()));
  fs::remove_all(frc);
  fs::remove_all(out);
  const std::string coupled = test::source_path("examples/coupled_duffing.toml");
  ASSERT_EQ(test::run_cli("frc " + coupled + " -o " + frc.string() + " -q").exit_code, 0);
  const nlohmann::json f = nlohmann::json::parse(std::ifstream(frc / "summary.json"));
  int bp = 0, other = 0;
  for (size_t k = 0; k < f["special_points"].size(); ++k) {
    if (f["special_points"][k]["type"] == "BP" && bp == 0) bp = static_cast<int>(k) + 1;
    if (f["special_points"][k]["type"] != "BP" && other == 0) other = static_cast<int>(k) + 1;
  }
  ASSERT_GT(bp, 0);
  const test::CliRun r =
      test::run_cli("switch " + coupled + " --from " + frc.string() + " --point " + std::to_string(bp) + " -o " + out.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(s["verb"], "switch");
  EXPECT_EQ(s["stop_reason"], "completed");
  EXPECT_EQ(test::csv_header(out / "branch.csv"), test::csv_header(frc / "branch.csv"));
  EXPECT_GT(s["points"].get<int>(), 10);
  if (other > 0) {
    const test::CliRun bad =
        test::run_cli("switch " + coupled + " --from " + frc.string() + " --point " + std::to_string(other) + " -o " + out.string());
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--point"), std::string::npos) << bad.err;
  }
  fs::remove_all(frc);
  fs::remove_all(out);
}

}  // namespace hbtrack_tests::file_branch_switching
