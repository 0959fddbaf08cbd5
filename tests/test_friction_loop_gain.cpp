// The static loop gain of frictional contacts (analysis/friction_loop_gain.hpp): against a
// flexibility computed by cofactors and a sense read from the element's own force, its sign
// with the sense of rotation, the cases where the motion sets the sense or the contact is rigid,
// and the shipped rotor 67 case in both senses.
#include <gtest/gtest.h>

#include <cmath>

#include "hbtrack/analysis/friction_loop_gain.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/tip_contact.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/friction_loop_gain_summary.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_friction_loop_gain {

using namespace hbtrack;
using Eigen::Matrix4d;

namespace {

// A 4-dof structure, the tip node on dofs 1-3 (r, t, z) and an extra dof 0 coupled to all of
// them: symmetric, diagonally dominant, hence positive definite (condition number about 10).
StructuralModel coupled_model() {
  StructuralModel m;
  m.dof_names = {"a", "tip_r", "tip_t", "tip_z"};
  m.stiffness.resize(4, 4);
  m.stiffness << 4.0, 1.0, 0.5, 0.0,  //
      1.0, 3.0, -1.6, 0.1,            //
      0.5, -1.6, 2.5, 0.3,            //
      0.0, 0.1, 0.3, 1.5;
  m.mass = Eigen::MatrixXd::Identity(4, 4);
  m.damping = Eigen::MatrixXd::Zero(4, 4);
  return m;
}

// stiffness, clearance, width, mu, radius, engine_order, rotation_speed
std::vector<double> tip_properties(double k, double mu, double engine_order, double rotation_speed = 0.0) {
  return {k, 0.01, 1e-3, mu, 0.2, engine_order, rotation_speed};
}

ElementList tip_on(const std::vector<double>& props) {
  auto e = std::make_shared<TipContact>(ContactLawKind::sqrt);
  e->dofs = {1, 2, 3};
  for (double p : props) e->properties.push_back(ParameterBinding::constant(p));
  return {e};
}

// (K^-1)_ij = C_ji / det K by cofactors: no factorisation shared with the code under test.
double det3(const Eigen::Matrix3d& a) {
  return a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
         a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
}
double cofactor(const Matrix4d& k, int i, int j) {
  Eigen::Matrix3d minor;
  for (int r = 0, mr = 0; r < 4; ++r) {
    if (r == i) continue;
    for (int c = 0, mc = 0; c < 4; ++c)
      if (c != j) minor(mr, mc++) = k(r, c);
    ++mr;
  }
  return ((i + j) % 2 ? -1.0 : 1.0) * det3(minor);
}
double inverse_entry(const Matrix4d& k, int i, int j) {
  double det = 0;
  for (int c = 0; c < 4; ++c) det += k(0, c) * cofactor(k, 0, c);
  return cofactor(k, j, i) / det;
}

// The ratio and gain from first principles: the element's force in contact at rest gives the
// loads on the structure (the element's force is the internal one: the structure feels -force),
// the cofactor flexibility their radial displacements; ratio = the outward push of friction
// over the inward push of the contact.
struct Expected {
  double ratio, gain;
};
Expected expected_from_force(const StructuralModel& m, const TipContact& e, const std::vector<double>& p, double omega) {
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(1, 3), v = Eigen::MatrixXd::Zero(1, 3);
  x(0, 0) = p[1] + 0.5;  // deep in contact: f_N = k g to 1e-7 relative, unused beyond its sign
  ElementResponse out;
  e.evaluate(x, v, omega, p, out, false);
  const Matrix4d k = m.stiffness;
  const double g_rr = inverse_entry(k, 1, 1), g_rt = inverse_entry(k, 1, 2);
  const double contact_inward = out.force(0, 0) * g_rr;  // -(radial displacement) from -f_N on r
  const double friction_outward = g_rt * -out.force(0, 1);
  const double ratio = friction_outward / contact_inward;
  return {ratio, p[0] * g_rr * (ratio - 1.0)};
}

TEST(FrictionLoopGain, EqualsTheCofactorFlexibilityAndTheElementsOwnFrictionSense) {
  const StructuralModel m = coupled_model();
  for (double engine_order : {-1.0, 1.0}) {
    const std::vector<double> p = tip_properties(3.0, 0.7, engine_order);
    const ElementList elements = tip_on(p);
    const std::vector<FrictionLoopGain> gains = friction_loop_gains(m, elements, {}, 1.0, 2.0);
    ASSERT_EQ(gains.size(), 1u);
    const FrictionLoopGain& g = gains[0];
    const Expected want = expected_from_force(m, static_cast<const TipContact&>(*elements[0]), p, 1.5);
    EXPECT_EQ(g.normal_dof, "tip_r");
    EXPECT_EQ(g.tangential_dof, "tip_t");
    EXPECT_TRUE(g.sense_from_law);
    EXPECT_NEAR(g.flexibility_nn, inverse_entry(m.stiffness, 1, 1), 1e-12 * g.flexibility_nn);
    // Both inverses are backward stable on a matrix of condition ~10: they agree to ~1e-15.
    EXPECT_NEAR(g.ratio, want.ratio, 1e-12 * std::abs(want.ratio)) << "engine_order " << engine_order;
    ASSERT_TRUE(g.gain.has_value());
    EXPECT_NEAR(*g.gain, want.gain, 1e-12 * std::abs(want.gain)) << "engine_order " << engine_order;
  }
}

TEST(FrictionLoopGain, ReversingTheRotationMovesTheRatioToTheOtherSideOfOne) {
  const StructuralModel m = coupled_model();
  // mu |G_rt| / G_rr is 1.47 here (G_rt > 0): friction wins when it pushes along +t, which the
  // casing does when it turns towards -t (engine_order -1).
  const double mu = 2.0, k = 40.0;
  const FrictionLoopGain a = friction_loop_gains(m, tip_on(tip_properties(k, mu, -1.0)), {}, 1.0, 2.0).at(0);
  const FrictionLoopGain b = friction_loop_gains(m, tip_on(tip_properties(k, mu, 1.0)), {}, 1.0, 2.0).at(0);
  EXPECT_EQ(a.sense, 1);
  EXPECT_EQ(b.sense, -1);
  EXPECT_DOUBLE_EQ(a.ratio, -b.ratio);
  EXPECT_GT(a.ratio, 1.0);
  EXPECT_LT(b.ratio, 1.0);
  EXPECT_TRUE(a.self_energising);
  EXPECT_FALSE(b.self_energising);
  // The stiffness at which the gain reaches 1, and a gain of 1/2 at half of it.
  ASSERT_TRUE(a.critical_stiffness.has_value());
  EXPECT_FALSE(b.critical_stiffness.has_value());
  EXPECT_NEAR(*a.critical_stiffness * a.flexibility_nn * (a.ratio - 1.0), 1.0, 1e-14);
  const FrictionLoopGain soft = friction_loop_gains(m, tip_on(tip_properties(0.5 * *a.critical_stiffness, mu, -1.0)), {}, 1.0, 2.0).at(0);
  EXPECT_NEAR(*soft.gain, 0.5, 1e-14);
  EXPECT_FALSE(soft.self_energising);
}

TEST(FrictionLoopGain, TakesTheWorseSenseWhereTheMotionSetsIt) {
  const StructuralModel m = coupled_model();
  // A casing whose rotation speed changes sign inside [1, 3] (W = omega - 2).
  const FrictionLoopGain turning = friction_loop_gains(m, tip_on(tip_properties(3.0, 0.7, 1.0, -2.0)), {}, 1.0, 3.0).at(0);
  EXPECT_FALSE(turning.sense_from_law);
  EXPECT_GT(turning.ratio, 0.0);
  // frictional_contact's slider slips either way; DLFT's contact is rigid: no gain, the ratio decides.
  StructuralModel two;
  two.dof_names = {"n", "t"};
  two.stiffness.resize(2, 2);
  two.stiffness << 2.0, 1.5, 1.5, 2.0;  // G_nt / G_nn = -0.75
  two.mass = two.damping = Eigen::Matrix2d::Identity();
  auto penalty = std::make_shared<FrictionalContact>(ContactFormulation::penalty);
  auto rigid = std::make_shared<FrictionalContact>(ContactFormulation::dlft);
  penalty->dofs = rigid->dofs = {0, 1};
  for (double p : {10.0, 5.0, 1.6, 0.0}) penalty->properties.push_back(ParameterBinding::constant(p));  // kn, kt, mu, preload
  for (double p : {1.6, 1.0, 0.0}) rigid->properties.push_back(ParameterBinding::constant(p));          // mu, epsilon, gap
  const std::vector<FrictionLoopGain> g = friction_loop_gains(two, {penalty, rigid}, {}, 1.0, 2.0);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_FALSE(g[0].sense_from_law);
  EXPECT_EQ(g[0].sense, -1);
  EXPECT_NEAR(g[0].ratio, 1.6 * 0.75, 1e-14);
  EXPECT_NEAR(*g[0].gain, 10.0 * (2.0 / 1.75) * (1.2 - 1.0), 1e-13);  // G_nn = 2 / (4 - 2.25)
  EXPECT_TRUE(g[0].self_energising);
  EXPECT_FALSE(g[1].gain.has_value());
  EXPECT_TRUE(g[1].self_energising);
  EXPECT_EQ(runs::friction_loop_gain_warnings(g).size(), 2u);
}

TEST(FrictionLoopGain, SaysWhyOnASingularStiffness) {
  StructuralModel free = coupled_model();
  free.stiffness.setZero();
  free.stiffness.bottomRightCorner(3, 3) = Eigen::Matrix3d::Identity();  // dof a is a rigid-body motion
  const FrictionLoopGain g = friction_loop_gains(free, tip_on(tip_properties(3.0, 0.7, -1.0)), {}, 1.0, 2.0).at(0);
  EXPECT_NE(g.note.find("singular"), std::string::npos) << g.note;
  EXPECT_FALSE(g.self_energising);
  EXPECT_TRUE(friction_loop_gains(free, {}, {}, 1.0, 2.0).empty());
}

// The issue 35 numbers (docs/rotor67.md): ratios 0.67, 0.98, 1.25, 1.46, 0.98 at n1-n5 in the
// geometry's sense, gains 1.60 and 1.45 at n3 and n4, the only ones above 1; in the reversed
// sense none above 1 at k = 1e8 (largest 0.81, n7), though n7 and n8 have ratios above 1.
TEST(FrictionLoopGain, Rotor67SelfEnergisesAtN3AndN4InTheGeometrysSenseOnly) {
  const std::string path = test::source_path("examples/rotor67/nominal.toml");
  const CaseDefinition c = load_case(path);
  const std::vector<FrictionLoopGain> geometry = runs::case_friction_loop_gains(c, c.nfrc.omega_start, c.nfrc.omega_end);
  ASSERT_EQ(geometry.size(), 9u);
  const double ratios[] = {0.667, 0.983, 1.250, 1.463, 0.984};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(geometry[static_cast<size_t>(i)].ratio, ratios[i], 2e-3) << "n" << i + 1;
  EXPECT_NEAR(*geometry[2].gain, 1.60, 0.01);
  EXPECT_NEAR(*geometry[3].gain, 1.45, 0.01);
  for (size_t i = 0; i < 9; ++i) EXPECT_EQ(geometry[i].self_energising, i == 2 || i == 3) << "n" << i + 1;
  EXPECT_EQ(runs::friction_loop_gain_warnings(geometry).size(), 2u);

  std::vector<std::string> reverse;  // as docs/rotor67.md reverses the sense
  for (int i = 0; i < 9; ++i) reverse.push_back("elements[" + std::to_string(i) + "].engine_order=1");
  const CaseDefinition r = load_case(path, reverse);
  const std::vector<FrictionLoopGain> reversed = runs::case_friction_loop_gains(r, r.nfrc.omega_start, r.nfrc.omega_end);
  double largest = -1e300;
  for (const FrictionLoopGain& g : reversed) {
    EXPECT_FALSE(g.self_energising) << g.normal_dof;
    largest = std::max(largest, *g.gain);
  }
  EXPECT_NEAR(largest, 0.81, 0.01);
  EXPECT_GT(reversed[6].ratio, 1.0);
  EXPECT_GT(reversed[7].ratio, 1.0);
  EXPECT_TRUE(runs::friction_loop_gain_warnings(reversed).empty());
}

}  // namespace

}  // namespace hbtrack_tests::file_friction_loop_gain
