// Stability: Hill's method against the monodromy matrix, and the stable/unstable segments of the
// Duffing example.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <complex>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/stability/hill.hpp"
#include "hbtrack/stability/monodromy.hpp"
#include "hbtrack/util/dense_eigen.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_stability {

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

// The distance from l to the nearest eigenvalue of Hill's pencil at (x, omega), all of them from
// its first-order form [[0, I], [-D2^-1 J, -D2^-1 D1]] by the dense eigensolver.
double distance_to_hill_spectrum(HarmonicBalance& hbm, const VectorXd& x, double omega, std::complex<double> l) {
  Eigen::MatrixXd jacobian, damping;
  hbm.hill_matrices(x, omega, jacobian, damping);
  const Eigen::Index size = jacobian.rows(), n = hbm.model().dofs();
  const Eigen::LLT<Eigen::MatrixXd> mass(hbm.model().mass);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * size, 2 * size);
  a.topRightCorner(size, size).setIdentity();
  for (Eigen::Index b = 0; b < size / n; ++b) {
    a.block(size + b * n, 0, n, size) = -mass.solve(jacobian.middleRows(b * n, n));
    a.block(size + b * n, size, n, size) = -mass.solve(damping.middleRows(b * n, n));
  }
  return (dense_eigenvalues(a).array() - l).abs().minCoeff();
}

}  // namespace

TEST(Stability, HillAgreesWithMonodromyOnDuffing) {
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/duffing.toml", {"harmonic_balance.harmonics=11", "harmonic_balance.samples=128"}, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
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

TEST(Stability, DuffingIsUnstableExactlyBetweenItsLimitPoints) {
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/duffing.toml", {}, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  ASSERT_EQ(r.continuation.special_points.size(), 2u);
  // On this branch (followed with increasing omega) the middle segment between the folds is
  // the one travelled backwards: unstable exactly where d omega / ds < 0.
  int unstable = 0;
  for (size_t i = 0; i < r.recorded.size(); ++i) {
    const bool backwards = r.continuation.points[i].tangent(hbm->unknowns()) < 0;
    ASSERT_GE(r.recorded[i].stable, 0);
    EXPECT_EQ(r.recorded[i].stable == 0, backwards) << "point " << i << " omega " << r.recorded[i].omega;
    unstable += r.recorded[i].stable == 0;
  }
  EXPECT_GT(unstable, 5);
}

TEST(Stability, LimitPointsAreLocatedOnTheAnalyticFold) {
  // With one harmonic the HBM is the one-term balance G(A, w) = ((1 - w^2 + b A)^2 + (c w)^2) A
  // - F^2 = 0 (A = a^2, b = 3/4 k3), whose folds also satisfy dG/dA = 0.
  const double c = 0.05, b = 0.075, f = 0.18;
  auto fold = [&](double w, double a2) {
    for (int it = 0; it < 50; ++it) {
      const double d = 1 - w * w + b * a2;
      const double g = (d * d + c * c * w * w) * a2 - f * f, ga = d * d + c * c * w * w + 2 * b * a2 * d;
      const double gw = (2 * d * (-2 * w) + 2 * c * c * w) * a2, gaa = 4 * b * d + 2 * b * b * a2;
      const double gaw = 2 * d * (-2 * w) + 2 * c * c * w + 2 * b * a2 * (-2 * w);
      Eigen::Matrix2d jac;
      jac << gw, ga, gaw, gaa;
      const Eigen::Vector2d step = jac.partialPivLu().solve(Eigen::Vector2d(-g, -ga));
      w += step(0);
      a2 += step(1);
    }
    return w;
  };
  CaseDefinition cd;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/duffing.toml", {"harmonic_balance.harmonics=1", "harmonic_balance.samples=16"}, cd, hbm);
  ASSERT_EQ(r.continuation.special_points.size(), 2u);
  for (const SpecialPoint& sp : r.continuation.special_points) {
    ASSERT_TRUE(sp.located);
    const double a2 = sp.u(1) * sp.u(1) + sp.u(2) * sp.u(2);
    EXPECT_NEAR(sp.lambda, fold(sp.lambda, a2), 1e-8 * sp.lambda);
  }
}

TEST(Stability, LocatedLimitPointsDoNotDependOnTheSteps) {
  std::vector<double> reference;
  for (const char* step : {"0.02", "0.005"}) {
    CaseDefinition c;
    std::unique_ptr<HarmonicBalance> hbm;
    const NfrcResult r =
        nfrc_of("examples/duffing.toml", {std::string("continuation.step=") + step, std::string("continuation.step_max=") + step}, c, hbm);
    ASSERT_EQ(r.continuation.special_points.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
      if (reference.size() < 2)
        reference.push_back(r.continuation.special_points[k].lambda);
      else
        EXPECT_NEAR(r.continuation.special_points[k].lambda, reference[k], 1e-8 * reference[k]);
    }
  }
}

namespace {
// The two-dof contact example with a smooth (sqrt) contact law, so that the harmonic balance
// converges spectrally and Hill's method can be compared with the monodromy matrix.
std::vector<std::string> smooth_two_dof(double width, int harmonics) {
  // Appended, not "text" + std::to_string(...): GCC 12 reports a false -Warray-bounds on that at -O3.
  std::string width_set = "elements[0].width=", harmonics_set = "harmonic_balance.harmonics=";
  width_set += std::to_string(width);
  harmonics_set += std::to_string(harmonics);
  return {"elements[0].type=\"regularized_contact\"",
          "elements[0].law=\"sqrt\"",
          width_set,
          "elements[0].stiffness=10",
          harmonics_set,
          "harmonic_balance.samples=512"};
}
}  // namespace

TEST(Stability, HillAgreesWithMonodromyOnTheTwoDofContactExample) {
  // Monodromy over thousands of steps per point: minutes under the sanitizers. The Duffing
  // comparison above runs the same Hill and monodromy code there.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers; run by the Release pass";
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  // A wide regularisation (2.0) keeps even the in-contact points resolved to 1e-8 at H = 30.
  std::vector<std::string> sets = smooth_two_dof(2.0, 30);
  sets.push_back("stability.method=\"none\"");
  const NfrcResult r = nfrc_of("examples/two_dof_contact.toml", sets, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  int checked = 0, in_contact = 0;
  const int n = 2, h = 30;
  for (size_t i = 0; i < r.continuation.points.size(); i += 5) {
    const BranchPoint& p = r.continuation.points[i];
    // Well resolved: the last harmonic of the contact dof is below 1e-8 of the first.
    const VectorXd full = hbm->expand(p.u, p.lambda);
    const double last = std::hypot(full((2 * h - 1) * n + 1), full(2 * h * n + 1));
    const double first = std::hypot(full(n + 1), full(2 * n + 1));
    if (last > 1e-8 * first) continue;
    const auto mh = sorted_moduli(hill_floquet(*hbm, p.u, p.lambda).multipliers);
    const auto mm = sorted_moduli(monodromy_floquet(*hbm, p.u, p.lambda, 8000).multipliers);
    for (size_t k = 0; k < mh.size(); ++k) EXPECT_NEAR(mh[k], mm[k], 1e-6 * mm[k]) << "omega " << p.lambda;
    ++checked;
    in_contact += r.recorded[i].outputs[1].max > 0.5;  // beyond the gap
  }
  EXPECT_GT(checked, 10);
  EXPECT_GT(in_contact, 2);
}

TEST(Stability, PeriodDoublingFoundWhereTheMonodromyMultipliersShowIt) {
  // Monodromy over thousands of steps per point: minutes under the sanitizers. The Duffing
  // comparison above runs the same Hill and monodromy code there.
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers; run by the Release pass";
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/two_dof_contact.toml", smooth_two_dof(0.05, 20), c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  // Brackets where a monodromy multiplier crosses -1 between consecutive points.
  std::vector<size_t> monodromy_pd;
  double previous = 0;
  for (size_t i = 0; i < r.continuation.points.size(); ++i) {
    const BranchPoint& p = r.continuation.points[i];
    const double test = period_doubling_test(monodromy_floquet(*hbm, p.u, p.lambda, 2000).multipliers);
    if (i > 0 && test * previous < 0) monodromy_pd.push_back(i);
    previous = test;
  }
  std::vector<const SpecialPoint*> detected;
  for (const SpecialPoint& sp : r.continuation.special_points)
    if (sp.type == SpecialPointType::period_doubling) detected.push_back(&sp);
  ASSERT_GE(monodromy_pd.size(), 2u);
  ASSERT_EQ(detected.size(), monodromy_pd.size());
  for (size_t k = 0; k < detected.size(); ++k) {
    // The located point lies between the two points that bracket the monodromy crossing.
    EXPECT_TRUE(detected[k]->located);
    EXPECT_GE(detected[k]->index, static_cast<int>(monodromy_pd[k]) - 1);
    EXPECT_LE(detected[k]->index, static_cast<int>(monodromy_pd[k]));
  }
}

TEST(Stability, SymmetryBreakingBranchPointsOfCoupledOscillators) {
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/coupled_duffing.toml", {}, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  int branch_points = 0;
  for (const SpecialPoint& sp : r.continuation.special_points) {
    if (sp.type != SpecialPointType::branch_point) continue;
    ++branch_points;
    ASSERT_TRUE(sp.located);
    // The response is symmetric (x1 = x2) and the Jacobian's null vector antisymmetric. The
    // Newton tolerance (1e-9) is amplified in the antisymmetric direction, where the Jacobian is
    // singular: symmetry holds to 1e-6, not to round-off.
    VectorXd res, r_omega;
    Eigen::MatrixXd jac;
    hbm->evaluate(sp.u, sp.lambda, res, &jac, &r_omega);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(jac, Eigen::ComputeFullV);
    const VectorXd null = svd.matrixV().col(jac.cols() - 1);
    const Eigen::Map<const Eigen::MatrixXd> u(sp.u.data(), 2, sp.u.size() / 2), v(null.data(), 2, null.size() / 2);
    EXPECT_LT((u.row(0) - u.row(1)).norm(), 1e-6 * u.norm());
    EXPECT_LT((v.row(0) + v.row(1)).norm(), 1e-6);
    EXPECT_LT(svd.singularValues().tail(1)(0), 1e-7 * svd.singularValues()(0));
  }
  EXPECT_EQ(branch_points, 2);
}

TEST(Stability, ArnoldiFindsTheRightmostHillExponents) {
  // The chain example (8 dofs, H = 10: a first-order Hill matrix of 336) at points of its NFRC:
  // shift-invert Arnoldi must return eigenvalues of Hill's pencil that decide stability as the
  // dense solver's do. Arnoldi sees only the members l + i k w of each family near the axis, the
  // dense solver picks the most central member (energy centroid, stability/hill.cpp); in the
  // truncated pencil the members' real parts differ by its truncation error (up to 5 % here).
  // So: Arnoldi's deciding exponent is an eigenvalue of the pencil (within 1e-8 of omega of one
  // of the dense solver's eigenvalues: the eigensolvers' accuracy), equals the dense one to 1e-8 of
  // omega where both picked the same member (same imaginary part modulo omega), and the stable
  // flags agree everywhere.
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r = nfrc_of("examples/chain_contact.toml",
                               {"harmonic_balance.harmonics=10", "harmonic_balance.samples=128", "stability.method=\"none\""}, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  int unstable = 0, same_members = 0;
  const auto deciding = [](const FloquetResult& f) {
    Eigen::Index largest = 0;
    f.exponents.real().maxCoeff(&largest);
    return f.exponents(largest);
  };
  for (size_t i = 0; i < r.continuation.points.size(); i += 3) {
    const BranchPoint& p = r.continuation.points[i];
    const FloquetResult dense = hill_floquet(*hbm, p.u, p.lambda, HillSolver::dense);
    const FloquetResult arnoldi = hill_floquet(*hbm, p.u, p.lambda, HillSolver::arnoldi);
    ASSERT_GT(arnoldi.exponents.size(), 0);
    // Arnoldi's deciding exponent is an eigenvalue of the pencil (l^2 D2 + l D1 + J), D2 = I x M.
    const std::complex<double> l = deciding(arnoldi);
    EXPECT_LT(distance_to_hill_spectrum(*hbm, p.u, p.lambda, l), 1e-8 * p.lambda)
        << "omega " << p.lambda << ": " << l << " is no eigenvalue";
    const double offset = std::abs(deciding(dense).imag()) - std::abs(l.imag());
    if (std::abs(offset - p.lambda * std::round(offset / p.lambda)) < 1e-6 * p.lambda) {
      ++same_members;
      EXPECT_NEAR(arnoldi.max_real, dense.max_real, 1e-8 * p.lambda) << "omega " << p.lambda;
    }
    EXPECT_EQ(arnoldi.stable, dense.stable) << "omega " << p.lambda;
    unstable += !dense.stable;
  }
  EXPECT_GT(unstable, 0) << "the comparison should include unstable points";
  EXPECT_GT(same_members, 0) << "no point compared to the eigensolvers' accuracy";
}

// Hill's shift-invert solver eliminates the dofs no element touches harmonic by harmonic; on a
// basis without the mean ([1, 2, 3, 4, 5]) a harmonic's cosine and sine are its first two
// coefficients. Grouped as if coefficient 0 were the mean, the solver paired the sine of one
// harmonic with the cosine of the next: its "exponents" were no eigenvalues of Hill's pencil, and
// they put 19 NS points on this branch, where the dense solver finds none. Every exponent it
// returns must be an eigenvalue of the pencil (to 1e-8 of omega, the eigensolvers' accuracy).
// (Which member of a family each solver keeps may still differ: see the test above.)
TEST(Stability, ArnoldiExponentsAreEigenvaluesOfThePencilOnABasisWithoutTheMean) {
  CaseDefinition c;
  std::unique_ptr<HarmonicBalance> hbm;
  const NfrcResult r =
      nfrc_of("examples/chain_contact.toml", {"harmonic_balance.harmonics=[1, 2, 3, 4, 5]", "stability.method=\"none\""}, c, hbm);
  ASSERT_EQ(r.continuation.summary.stop_reason, StopReason::reached_end);
  int compared = 0;
  for (size_t i = 0; i < r.continuation.points.size(); i += 8) {
    const BranchPoint& p = r.continuation.points[i];
    const FloquetResult arnoldi = hill_floquet(*hbm, p.u, p.lambda, HillSolver::arnoldi);
    ASSERT_GT(arnoldi.exponents.size(), 0);
    for (Eigen::Index k = 0; k < arnoldi.exponents.size(); ++k)
      EXPECT_LT(distance_to_hill_spectrum(*hbm, p.u, p.lambda, arnoldi.exponents(k)), 1e-8 * p.lambda)
          << "omega " << p.lambda << ": " << arnoldi.exponents(k) << " is no eigenvalue";
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

}  // namespace hbtrack_tests::file_stability
