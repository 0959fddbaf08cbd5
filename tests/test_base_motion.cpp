// Imposed base motion in relative coordinates: the base-excited case gives the same HBM
// solution as the equivalent forced problem built by hand (a nonlinear model, to the Newton
// tolerance), and on a linear oscillator the closed-form relative FRF for each kind of motion.
#include <gtest/gtest.h>

#include <complex>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_base_motion {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;
namespace fs = std::filesystem;

// A two-mass chain on a shaker table: x1 on the table through k = 1, x2 on x1; a cubic spring
// between x1 and the table. Everything the table carries moves with it (influence 1).
const char* kChain = R"(
[model]
dofs = ["x1", "x2"]
M = [[1.0, 0.0], [0.0, 0.5]]
K = [[2.0, -1.0], [-1.0, 1.0]]
[damping]
C = [[0.04, -0.02], [-0.02, 0.02]]
EXCITATION
[[elements]]
type = "cubic_spring"
dofs = ["x1"]
cubic_stiffness = 0.5
[harmonic_balance]
harmonics = 5
samples = 64
[continuation]
omega_start = 0.3
omega_end = 2.0
[[outputs]]
name = "x2"
dof = "x2"
)";

// `text` with its EXCITATION line replaced, written to a per-process folder (ctest runs the
// tests in parallel processes).
fs::path write_case(const std::string& name, std::string text, const std::string& excitation) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_base_motion_" + std::to_string(getpid()));
  fs::create_directories(dir);
  if (const size_t at = text.find("EXCITATION"); at != std::string::npos) text.replace(at, 10, excitation);
  const fs::path p = dir / (name + ".toml");
  std::ofstream(p) << text;
  return p;
}

TEST(BaseMotion, SameSolutionAsTheEquivalentForcedProblem) {
  // Base displacement U = 0.05 cos + 0.02 sin at harmonic 1: the forcing M r (omega^2) U built by
  // hand at each omega (r = [1, 1], M r = [1, 0.5]), a fixed [[forcing]] of the same size.
  const CaseDefinition base = load_case(
      write_case("base", kChain, "[base_motion]\nkind = \"displacement\"\ndofs = [\"x1\", \"x2\"]\ncos = 0.05\nsin = 0.02\n").string());
  ASSERT_TRUE(base.base_motion.has_value());
  HarmonicBalance base_hbm(base.model, base.elements, base.parameters, base.harmonic_balance);
  for (double omega : {0.5, 0.9, 1.6}) {
    const double w2 = omega * omega;
    char text[400];  // every digit: the hand-built forcing must be the same numbers
    std::snprintf(text, sizeof text, "[[forcing]]\ncos = [%.17g, %.17g]\nsin = [%.17g, %.17g]\n", 0.05 * w2, 0.025 * w2, 0.02 * w2,
                  0.01 * w2);
    const CaseDefinition hand = load_case(write_case("hand", kChain, text).string());
    HarmonicBalance hand_hbm(hand.model, hand.elements, hand.parameters, hand.harmonic_balance);
    // Newton to 1e-12 of the force scale on both: the solutions agree to that order.
    const FixedFrequencySolution a = solve_at_frequency(base_hbm, omega, base.outputs, 1e-12, 60);
    const FixedFrequencySolution b = solve_at_frequency(hand_hbm, omega, hand.outputs, 1e-12, 60);
    ASSERT_TRUE(a.converged && b.converged) << omega;
    const double difference = (a.x - b.x).cwiseAbs().maxCoeff() / b.x.cwiseAbs().maxCoeff();
    std::printf("[ measured ] omega %.2f: base-excited vs hand-built forcing, largest difference %.1e of the largest harmonic\n", omega,
                difference);
    EXPECT_LT(difference, 1e-10) << omega;
    // And the residual of one at the other's solution is at the Newton tolerance.
    VectorXd r;
    base_hbm.evaluate(b.x, omega, r);
    EXPECT_LT(r.cwiseAbs().maxCoeff(), 1e-10 * 0.05 * w2) << omega;
  }
}

TEST(BaseMotion, LinearOscillatorFollowsTheClosedFormRelativeFrf) {
  // m z'' + c z' + k z = -m u_b'': z = m (h w)^2 U / (k - m (h w)^2 + i c h w) for a displacement
  // U; a velocity V is U = V / (i h w) and an acceleration A is U = -A / (h w)^2.
  const double m = 2.0, k = 3.0, c = 0.1, a = 1.5;
  struct Kind {
    const char* name;
    std::complex<double> (*displacement)(std::complex<double> given, double hw);
  };
  const Kind kinds[] = {{"displacement", [](std::complex<double> u, double) { return u; }},
                        {"velocity", [](std::complex<double> v, double hw) { return v / std::complex<double>(0, hw); }},
                        {"acceleration", [](std::complex<double> acc, double hw) { return -acc / (hw * hw); }}};
  for (const Kind& kind : kinds) {
    for (int harmonic : {1, 2}) {
      // Appended, not one chain of +: GCC 12 at -O1 reports a false -Warray-bounds on the chain
      // in some unity batches.
      std::string text = "[model]\ndofs = [\"z\"]\nM = [[2.0]]\nK = [[3.0]]\n[damping]\nC = [[0.1]]\n[base_motion]\nkind = \"";
      text += kind.name;
      text += "\"\ndofs = [\"z\"]\nharmonic = ";
      text += std::to_string(harmonic);
      text += "\ncos = 0.3\nsin = -0.2\n[parameters]\namplitude = 1.5\n[harmonic_balance]\nharmonics = 3\n";
      text += "[continuation]\nomega_start = 0.5\nomega_end = 2.0\n";
      const CaseDefinition cd = load_case(write_case("linear", text, "").string());
      HarmonicBalance hbm(cd.model, cd.elements, cd.parameters, cd.harmonic_balance);
      for (double omega : {0.4, 1.2, 2.3}) {
        const double hw = harmonic * omega;
        const std::complex<double> u = kind.displacement(a * std::complex<double>(0.3, 0.2), hw);  // cos - i sin
        const std::complex<double> z = m * hw * hw * u / std::complex<double>(k - m * hw * hw, c * hw);
        const VectorXd x = hbm.linear_solution(omega);  // [a0, a1, b1, a2, b2, ...], a_h - i b_h = z
        EXPECT_NEAR(x(2 * harmonic - 1), z.real(), 1e-12 * std::abs(z)) << kind.name << " h " << harmonic << " omega " << omega;
        EXPECT_NEAR(x(2 * harmonic), -z.imag(), 1e-12 * std::abs(z)) << kind.name << " h " << harmonic << " omega " << omega;
      }
    }
  }
}

}  // namespace hbtrack_tests::file_base_motion
