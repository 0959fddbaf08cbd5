// Scalar elements along any direction over many dofs (NLvib's force direction vectors:
// d = w.x, force w f(d)), as a case file writes them. A substructure whose node is turned into
// another frame (x' = T x, T = blkdiag(R, 1)) with its elements along the turned directions
// (w' = T w) is the same problem: its residual is T r(x) and its Jacobian P J P^T (P = T on each
// harmonic's block) to round-off, its solutions P x; and the Jacobian of the turned problem
// against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_element_directions {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;
namespace fs = std::filesystem;

namespace {

// Node n1 (x, y) joined to a dof n2 along x: masses, springs to the ground and between them.
const MatrixXd kMass = Eigen::Vector3d(1.0, 1.0, 2.0).asDiagonal();
const MatrixXd kStiffness = (MatrixXd(3, 3) << 2.0, 0.0, -1.0, 0.0, 2.25, 0.0, -1.0, 0.0, 1.5).finished();
const VectorXd kForce = Eigen::Vector3d(0.3, 0.2, -0.1);

std::string toml_row(const Eigen::Ref<const VectorXd>& v) {
  std::ostringstream out;
  out.precision(17);
  out << "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out << (i ? ", " : "") << v(i);
  return out.str() + "]";
}

std::string toml_matrix(const MatrixXd& m) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) out += (i ? ", " : "") + toml_row(m.row(i).transpose());
  return out + "]";
}

// The case in the frame x' = T x: every matrix, the forcing and each element's direction turned.
// Elements: a cubic spring on n1.x alone (w = [1] in the original frame), a Jenkins element
// between n1 along (0.6, 0.8) and n2 (w = [0.6, 0.8, -1]), a penalty contact of n1 along
// (-0.8, 0.6) with a gap, a quadratic damper along (0.6, 0.8, -1).
fs::path write_case(const MatrixXd& t, const std::string& name) {
  const std::string dofs = "[\"n1_x\", \"n1_y\", \"n2_x\"]";
  std::string text = "[model]\ndofs = " + dofs + "\nM = " + toml_matrix(t * kMass * t.transpose()) +
                     "\nK = " + toml_matrix(t * kStiffness * t.transpose()) + "\n[damping]\nrayleigh = [0.0, 0.02]\n" +
                     "[[forcing]]\ncos = " + toml_row(t * kForce) + "\n";
  const auto element = [&](const std::string& type, const VectorXd& w, const std::string& properties) {
    text += "[[elements]]\ntype = \"" + type + "\"\ndofs = " + dofs + "\nweights = " + toml_row(t * w) + "\n" + properties;
  };
  element("cubic_spring", Eigen::Vector3d(1.0, 0.0, 0.0), "cubic_stiffness = 0.5\n");
  element("elastic_dry_friction", Eigen::Vector3d(0.6, 0.8, -1.0), "stiffness = 3.0\nlimit_force = 0.05\n");
  element("unilateral_spring", Eigen::Vector3d(-0.8, 0.6, 0.0), "stiffness = 4.0\ngap = 0.05\n");
  element("power_damper", Eigen::Vector3d(0.6, 0.8, -1.0), "coefficient = 0.05\n");
  text +=
      "[harmonic_balance]\nharmonics = 5\nsamples = 128\ncondensation = \"none\"\n"
      "[continuation]\nomega_start = 0.5\nomega_end = 2.0\n[stability]\nmethod = \"none\"\n";
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_directions_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / (name + ".toml");
  std::ofstream(path) << text;
  return path;
}

MatrixXd turn(double angle) {
  MatrixXd t = MatrixXd::Identity(3, 3);
  t.topLeftCorner(2, 2) << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return t;
}

// T on each harmonic's block of the unknowns (harmonic-major: index = coefficient * 3 + dof).
MatrixXd on_every_harmonic(const MatrixXd& t, Eigen::Index unknowns) {
  MatrixXd p = MatrixXd::Zero(unknowns, unknowns);
  for (Eigen::Index c = 0; c < unknowns / 3; ++c) p.block(3 * c, 3 * c, 3, 3) = t;
  return p;
}

}  // namespace

TEST(ElementDirections, ATurnedFrameIsTheSameProblem) {
  const CaseDefinition original = load_case(write_case(MatrixXd::Identity(3, 3), "original").string());
  const MatrixXd t = turn(0.7);
  const CaseDefinition turned = load_case(write_case(t, "turned").string());
  HarmonicBalance a(original.model, original.elements, original.parameters, original.harmonic_balance);
  HarmonicBalance b(turned.model, turned.elements, turned.parameters, turned.harmonic_balance);
  ASSERT_EQ(a.unknowns(), b.unknowns());
  const MatrixXd p = on_every_harmonic(t, a.unknowns());
  // A motion in stick-slip and in and out of contact: amplitudes near 0.1.
  VectorXd x = VectorXd::Zero(a.unknowns());
  for (Eigen::Index i = 0; i < x.size(); ++i)
    x(i) = 0.15 * std::cos(1.7 * static_cast<double>(i) + 0.4) / (1.0 + static_cast<double>(i / 6));
  for (double omega : {0.8, 1.3}) {
    VectorXd ra, rb;
    MatrixXd ja, jb;
    a.evaluate(x, omega, ra, &ja, nullptr);
    b.evaluate(p * x, omega, rb, &jb, nullptr);
    EXPECT_LT((rb - p * ra).cwiseAbs().maxCoeff(), 1e-13 * ra.cwiseAbs().maxCoeff()) << "omega " << omega;
    EXPECT_LT((jb - p * ja * p.transpose()).cwiseAbs().maxCoeff(), 1e-13 * ja.cwiseAbs().maxCoeff()) << "omega " << omega;
    EXPECT_LT(test::residual_jacobian_error(b, p * x, omega, 1e-7), 1e-6) << "omega " << omega;
    // The solutions: Newton from rest in each frame lands on the same motion, turned.
    const FixedFrequencySolution sa = solve_at_frequency(a, omega, original.outputs, 1e-13, 100);
    const FixedFrequencySolution sb = solve_at_frequency(b, omega, turned.outputs, 1e-13, 100);
    ASSERT_TRUE(sa.converged && sb.converged) << "omega " << omega;
    std::printf("[ measured ] omega %.1f: residual %.1e, Jacobian %.1e, solution %.1e (relative to the largest entry)\n", omega,
                (rb - p * ra).cwiseAbs().maxCoeff() / ra.cwiseAbs().maxCoeff(),
                (jb - p * ja * p.transpose()).cwiseAbs().maxCoeff() / ja.cwiseAbs().maxCoeff(),
                (sb.x - p * sa.x).cwiseAbs().maxCoeff() / sa.x.cwiseAbs().maxCoeff());
    EXPECT_LT((sb.x - p * sa.x).cwiseAbs().maxCoeff(), 1e-11 * sa.x.cwiseAbs().maxCoeff()) << "omega " << omega;
  }
}

}  // namespace hbtrack_tests::file_element_directions
