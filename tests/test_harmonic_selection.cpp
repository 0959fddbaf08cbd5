// Harmonic selection (harmonic_balance.harmonics = [1, 3, 5, 7]) and subharmonic bases
// (harmonic_balance.subharmonic = nu): the basis' operators, the analytic Jacobian against finite
// differences, the odd-harmonic Duffing against the full basis, and the bad lists' errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/hbm/fourier_basis.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_harmonic_selection {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(HarmonicSelection, BasisOperatorsAreThoseOfTheDenseBasisRestricted) {
  const int samples = 64;
  const FourierBasis odd(std::vector<int>{1, 3, 5, 7}, samples), mixed(std::vector<int>{0, 2, 3, 6}, samples);
  for (const FourierBasis* b : {&odd, &mixed}) {
    const int nc = b->coefficients();
    EXPECT_EQ(nc, b->has_mean() ? 7 : 8);
    EXPECT_LT((b->analysis() * b->synthesis() - MatrixXd::Identity(nc, nc)).cwiseAbs().maxCoeff(), 1e-12);
    // Gamma^-1 diag(g) Gamma by the product-to-sum identities against the sampled product.
    const VectorXd g = VectorXd::LinSpaced(samples, -1.0, 2.0).array().sin() + 0.3;
    const VectorXd g_coeffs = b->product_analysis() * g;
    MatrixXd product(nc, nc);
    b->product_matrix(g_coeffs.data(), product);
    const MatrixXd sampled = b->analysis() * g.asDiagonal() * b->synthesis();
    EXPECT_LT((product - sampled).cwiseAbs().maxCoeff(), 1e-12);
    // nabla: right multiplication and derivative() agree with d/dtau of the synthesis.
    MatrixXd identity = MatrixXd::Identity(nc, nc);
    b->right_multiply_derivative(identity);
    EXPECT_LT((b->synthesis() * identity - b->derivative_synthesis()).cwiseAbs().maxCoeff(), 1e-12);
    const VectorXd c = VectorXd::LinSpaced(nc, 0.5, -1.0);
    VectorXd dc;
    b->derivative(c, 1, dc);
    EXPECT_LT((b->synthesis() * dc - b->derivative_synthesis() * c).cwiseAbs().maxCoeff(), 1e-12);
    // The dense layout 0..H of the basis' largest harmonic H (7 for odd, 6 for mixed): the same
    // signal, and back.
    const VectorXd full = b->to_dense(c, 1);
    const FourierBasis dense_to_h(static_cast<int>(full.size() - 1) / 2, samples);
    ASSERT_EQ(dense_to_h.coefficients(), full.size());
    EXPECT_LT((dense_to_h.synthesis() * full - b->synthesis() * c).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_EQ(b->from_dense(full, 1), c);
  }
  EXPECT_EQ(odd.harmonic_of(0), 1);
  EXPECT_EQ(odd.cosine_index(3), 2);
  EXPECT_EQ(odd.cosine_index(2), -1);
  EXPECT_THROW(FourierBasis(std::vector<int>{3, 1}, 64), std::invalid_argument);
}

struct Selection {
  std::vector<int> harmonics;
  int subharmonic;
  const char* condensation;
};

// The contact fixture (tip contact with friction, a cubic spring, tanh friction, linear dofs
// condensed) on a selected or subharmonic basis. Its forcing has harmonics 1 and 2.
HarmonicBalance selected_model(const Selection& s) {
  test::ContactFixture f = test::contact_fixture(false, 1.0);
  HarmonicBalanceOptions o;
  o.select(s.harmonics);
  o.subharmonic = s.subharmonic;
  o.samples = 64;
  o.condensation = parse_condensation(s.condensation);
  return HarmonicBalance(f.model, f.elements, f.parameters, o);
}

class SelectedBasisDerivatives : public ::testing::TestWithParam<Selection> {};

// Steps and tolerance as tests/test_harmonic_balance.cpp: unknowns O(0.1), h = 1e-7 leaves a
// truncation error ~1e-14 and round-off ~1e-9 relative; an error in any term exceeds 1e-6.
TEST_P(SelectedBasisDerivatives, MatchFiniteDifferences) {
  HarmonicBalance hbm = selected_model(GetParam());
  const int q = hbm.retained_dofs();
  std::srand(11);
  VectorXd x = 0.01 * VectorXd::Random(hbm.unknowns());
  // The tip's radial dof enters contact over part of the period.
  const int first = hbm.basis().cosine_index(hbm.subharmonic());
  x(first * q) = 0.08;
  x((first + 1) * q + 1) = 0.05;
  const double omega = 1.3;
  VectorXd r, r_omega;
  MatrixXd jac;
  hbm.evaluate(x, omega, r, &jac, &r_omega);
  auto residual = [&](const VectorXd& xx) {
    VectorXd rr;
    hbm.evaluate(xx, omega, rr);
    return rr;
  };
  EXPECT_LT(test::relative_error(jac, test::fd_jacobian(residual, x, 1e-7)), 1e-6) << "dR/dx";
  auto at_omega = [&](double w) {
    VectorXd rr;
    hbm.evaluate(x, w, rr);
    return rr;
  };
  EXPECT_LT(test::relative_error(r_omega, test::central_difference(at_omega, omega, 1e-7)), 1e-6) << "dR/domega";
  for (const std::string name : {"amplitude", "mu"}) {
    const int p = hbm.parameters().find(name);
    const double p0 = hbm.parameters().value(p);
    auto at_p = [&](double value) {
      hbm.set_parameter(p, value);
      VectorXd rr;
      hbm.evaluate(x, omega, rr);
      return rr;
    };
    const VectorXd fd = test::central_difference(at_p, p0, 1e-7);
    hbm.set_parameter(p, p0);
    EXPECT_LT(test::relative_error(hbm.parameter_derivative(x, omega, p), fd), 1e-6) << "dR/d" << name;
  }
  // The time-domain adjoint product against the assembled Jacobian's nonlinear part.
  VectorXd w = VectorXd::Random(hbm.unknowns()), jt_w;
  hbm.nonlinear_adjoint_products(x, omega, w, jt_w);
  const MatrixXd linear = jac - test::fd_jacobian([&](const VectorXd& xx) { return hbm.nonlinear_forces(xx, omega); }, x, 1e-7);
  VectorXd r_lin;
  MatrixXd j_full;
  hbm.evaluate(x, omega, r_lin, &j_full);
  EXPECT_LT(test::relative_error(jt_w, (j_full - linear).transpose() * w), 1e-6) << "J_nl^T w";
}

INSTANTIATE_TEST_SUITE_P(Bases, SelectedBasisDerivatives,
                         ::testing::Values(Selection{{1, 2, 4}, 1, "schur"}, Selection{{0, 1, 2, 5}, 1, "modal"},
                                           Selection{{0, 1, 2, 3, 4, 5, 6}, 2, "schur"}, Selection{{1, 2, 3, 4, 6}, 2, "none"}),
                         [](const ::testing::TestParamInfo<Selection>& param_info) {
                           std::string name = param_info.param.condensation;
                           name += "_nu";
                           name += std::to_string(param_info.param.subharmonic);
                           for (int k : param_info.param.harmonics) {
                             name += '_';  // appended one by one: GCC 12's false -Wstringop-overflow on "_" + ...
                             name += std::to_string(k);
                           }
                           return name;
                         });

CaseDefinition duffing(const std::string& harmonics) {
  return load_case(test::source_path("examples/duffing.toml"),
                   {"harmonic_balance.harmonics=" + harmonics, "continuation.tolerance=1e-11", "continuation.step=0.05"});
}

// Newton on the harmonic balance alone at fixed omega, to max |R| <= 1e-13 of the forcing.
VectorXd polish(HarmonicBalance& hbm, VectorXd x, double omega) {
  VectorXd r;
  MatrixXd j;
  for (int it = 0; it < 20; ++it) {
    hbm.evaluate(x, omega, r, &j);
    if (r.cwiseAbs().maxCoeff() <= 1e-13 * 0.18) break;
    x -= j.partialPivLu().solve(r);
  }
  return x;
}

// Duffing's restoring force is odd and its forcing harmonic 1, so its periodic response has odd
// harmonics only: balancing [1, 3, 5, 7] must give the full H = 7 solution (whose even harmonics
// vanish) with 8 unknowns instead of 15, its folds and its stability.
TEST(HarmonicSelection, OddHarmonicDuffingEqualsTheFullBasis) {
  const CaseDefinition odd_case = duffing("[1, 3, 5, 7]"), full_case = duffing("7");
  HarmonicBalance odd(odd_case.model, odd_case.elements, odd_case.parameters, odd_case.harmonic_balance);
  HarmonicBalance full(full_case.model, full_case.elements, full_case.parameters, full_case.harmonic_balance);
  EXPECT_EQ(odd.unknowns(), 8);
  EXPECT_EQ(full.unknowns(), 15);
  const NfrcResult odd_nfrc = compute_nfrc(odd, odd_case.nfrc, odd_case.outputs);
  ASSERT_EQ(odd_nfrc.continuation.summary.stop_reason, StopReason::reached_end);
  double worst = 0, worst_even = 0;
  int compared = 0;
  for (size_t i = 0; i < odd_nfrc.continuation.points.size(); i += 2) {
    const BranchPoint& p = odd_nfrc.continuation.points[i];
    // The odd solution, and the full basis' solution from it disturbed in every harmonic by 1e-3
    // of its size (Newton must come back onto the same solution), both polished at the same omega.
    const VectorXd x_odd = polish(odd, p.u, p.lambda);
    const VectorXd disturbed = odd.basis().to_dense(x_odd, 1) + 1e-3 * x_odd.cwiseAbs().maxCoeff() * VectorXd::Random(15);
    const VectorXd x_full = polish(full, disturbed, p.lambda);
    const double scale = x_full.cwiseAbs().maxCoeff();
    worst = std::max(worst, (odd.basis().from_dense(x_full, 1) - x_odd).cwiseAbs().maxCoeff() / scale);
    for (int k = 0; k <= 6; k += 2) {
      const int c = k == 0 ? 0 : 2 * k - 1;
      worst_even = std::max(worst_even, std::abs(x_full(c)) / scale);
      if (k > 0) worst_even = std::max(worst_even, std::abs(x_full(c + 1)) / scale);
    }
    // Stability: Hill over the odd harmonics decides as over all of them (the fold's critical
    // eigenvector is odd; no symmetry breaking on this branch).
    EXPECT_EQ(odd_nfrc.recorded[i].stable, floquet(full, x_full, p.lambda, full_case.nfrc.stability).stable ? 1 : 0)
        << "omega " << p.lambda;
    ++compared;
  }
  EXPECT_GT(compared, 20);
  std::printf("[ measured ] %d points: odd vs full basis %.2e, even harmonics of the full solution %.2e (of max |x|)\n", compared, worst,
              worst_even);
  // Both Newton iterations reach 1e-13 of the forcing; the solutions are as close (1e-8 is the
  // issue's bound, measured ~1e-13).
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_even, 1e-8);
  // The folds of both NFRCs: located on the same test function (det J's sign via the tangent),
  // to the locator's precision.
  const NfrcResult full_nfrc = compute_nfrc(full, full_case.nfrc, full_case.outputs);
  std::vector<double> odd_lps, full_lps;
  for (const auto& sp : odd_nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point) odd_lps.push_back(sp.lambda);
  for (const auto& sp : full_nfrc.continuation.special_points)
    if (sp.type == SpecialPointType::limit_point) full_lps.push_back(sp.lambda);
  ASSERT_EQ(odd_lps.size(), 2u);
  ASSERT_EQ(full_lps.size(), odd_lps.size());
  for (size_t i = 0; i < odd_lps.size(); ++i) EXPECT_NEAR(odd_lps[i], full_lps[i], 1e-8);
}

TEST(HarmonicSelection, ABadListIsRefusedNamingTheFileTheFieldAndTheRule) {
  std::ifstream example(test::source_path("examples/duffing.toml"));
  const std::string text((std::istreambuf_iterator<char>(example)), std::istreambuf_iterator<char>());
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("hbtrack_bad_harmonics_" + std::to_string(getpid()) + ".toml");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[3, 1]", "harmonic_balance.harmonics: a list of harmonics must be sorted and unique (increasing), got [3, 1]"},
      {"[1, 1, 3]", "must be sorted and unique"},
      {"[-1, 1]", "harmonic_balance.harmonics: a list of harmonics must hold integers >= 0"},
      {"[0]", "harmonic_balance.harmonics: a list of harmonics needs one >= 1"},
      {"[]", "harmonic_balance.harmonics: an empty list"},
      {"[1, 2.5]", "harmonic_balance.harmonics[1]: expected an integer"},
      {"[0, 2, 4]", ":15: forcing[0].harmonic: harmonic 1 is not in the list harmonic_balance.harmonics"}};
  for (const auto& [list, message] : cases) {
    std::string bad = text;
    bad.replace(bad.find("harmonics = 7"), 13, "harmonics = " + list);
    std::ofstream(path) << bad;
    try {
      load_case(path.string(), {});
      ADD_FAILURE() << list << " was accepted";
    } catch (const CaseError& e) {
      const std::string what = e.what();
      // The file and the line: of the list (27), or of the forcing's harmonic (15).
      EXPECT_NE(what.find(path.filename().string() + (message[0] == ':' ? "" : ":27: ")), std::string::npos) << what;
      EXPECT_NE(what.find(message), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
    }
  }
  std::filesystem::remove(path);
  // On the command line: the --set override is named instead of a file.
  try {
    load_case(test::source_path("examples/duffing.toml"), {"harmonic_balance.harmonics=[3, 1]"});
    ADD_FAILURE() << "[3, 1] was accepted";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("--set: harmonic_balance.harmonics: a list of harmonics must be sorted"), std::string::npos)
        << e.what();
  }
}

TEST(HarmonicSelection, TheCliNamesTheColumnsByTheHarmonicsBalanced) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / ("hbtrack_selection_" + std::to_string(getpid()));
  std::filesystem::remove_all(out);
  const std::string duffing_case = test::source_path("examples/duffing.toml");
  const test::CliRun run =
      test::run_cli("frc " + duffing_case + " --set 'harmonic_balance.harmonics=[1, 3, 5, 7]' -o " + out.string() + " -q");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> header = test::csv_header(out / "branch.csv");
  const std::vector<std::string> expected{"omega", "stable", "max_x",    "min_x",    "h1_x",     "h3_x",
                                          "h5_x",  "h7_x",   "phase1_x", "phase3_x", "phase5_x", "phase7_x"};
  EXPECT_EQ(header, expected);
  EXPECT_EQ(test::csv_header(out / "states.csv").size(), 9u);  // omega and x's 8 coefficients (x_c1, x_s1, ..., x_s7)
  std::ifstream summary(out / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"harmonics\": [\n"), std::string::npos) << "the list as given in options.harmonic_balance";
  // A verb that reads the folder back (simulate --from) gets the same basis: it starts on the
  // point (3 periods do not settle it: exit 1, not 2 for a layout mismatch).
  const test::CliRun sim = test::run_cli("simulate " + duffing_case + " --from " + out.string() + " --point 5 --max-periods 3 -o " +
                                         (out / "sim").string() + " -q");
  EXPECT_NE(sim.exit_code, 2) << sim.err;
  EXPECT_TRUE(std::filesystem::exists(out / "sim" / "summary.json")) << sim.err;
  std::filesystem::remove_all(out);
}

}  // namespace hbtrack_tests::file_harmonic_selection
