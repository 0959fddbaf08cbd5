// Scaling benchmark on the chain-with-contact example: NFRC wall time, Newton iterations, the
// cost of one Newton iteration relative to one dense LU of the bordered condensed system, both
// measured in this run (ratios survive a noisy shared machine; absolute times do not), and where
// the time goes (util/phase_timer.hpp), as n, H and the number of samples N grow. Plain Newton
// (continuation.reuse_factorization = false), so that every iteration does the same work: a
// Jacobian, an LU, a solve.
//
//   build/bench/bench_chain [--quick]      prints a Markdown table
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/stability/hill.hpp"
#include "bench_support.hpp"

namespace {

using hbtrack::bench::Breakdown;
using hbtrack::bench::Clock;
using hbtrack::bench::dense_lu_seconds;
using hbtrack::bench::median;
using hbtrack::bench::seconds_since;

// The chain example with n masses, the contact and the forcing at the free end, the range
// around the first mode, and the forcing scaled so that the linear peak is three gaps.
// samples = 0: the smallest power of two >= max(64, 16 (H + 1)).
std::string chain_case(int n, int harmonics, const std::string& condensation, int samples) {
  const double omega1 = 2.0 * std::sin(std::numbers::pi / (2.0 * (2 * n + 1)));
  if (samples == 0) {
    samples = 64;
    while (samples < 16 * (harmonics + 1)) samples *= 2;
  }
  char text[2048];
  std::snprintf(text, sizeof text,
                "[model]\nchain = { count = %d, mass = 1.0, stiffness = 1.0 }\n"
                "[damping]\nmodal_ratios = [0.05]\n"
                "[[forcing]]\ndof = \"x%d\"\nharmonic = 1\ncos = 1.0\n"
                "[parameters]\namplitude = 1.0\nclearance = 0.05\n"
                "[[elements]]\ntype = \"unilateral_spring\"\ndofs = [\"x%d\"]\nstiffness = 2.0\ngap = \"clearance\"\n"
                "[harmonic_balance]\nharmonics = %d\nsamples = %d\ncondensation = \"%s\"\n"
                "[continuation]\nomega_start = %.17g\nomega_end = %.17g\nstep = 0.02\n"
                "[stability]\nmethod = \"none\"\n",
                n, n, n, harmonics, samples, condensation.c_str(), 0.6 * omega1, 1.6 * omega1);
  return text;
}

struct Row {
  int n, harmonics, samples, unknowns, points, newton;
  std::string condensation, stop;
  double wall, lu, per_iteration, stability;
  Breakdown breakdown;
};

Row measure(int n, int harmonics, const std::string& condensation, int samples = 0) {
  const auto path = std::filesystem::temp_directory_path() / "hbtrack_bench_chain.toml";
  std::ofstream(path) << chain_case(n, harmonics, condensation, samples);
  hbtrack::CaseDefinition c = hbtrack::load_case(path.string());
  c.nfrc.continuation.reuse_factorization = false;
  {
    hbtrack::HarmonicBalance probe(c.model, c.elements, c.parameters, c.harmonic_balance);
    const double peak = hbtrack::automatic_length_scale(probe, c.nfrc.omega_start, c.nfrc.omega_end);
    c.parameters.set("amplitude", 3.0 * 0.05 / peak);
  }
  hbtrack::HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  hbtrack::PhaseTimes::reset();
  const auto t0 = Clock::now();
  const hbtrack::NfrcResult r = hbtrack::compute_nfrc(hbm, c.nfrc, {});
  const double wall = seconds_since(t0);
  const Breakdown breakdown = Breakdown::of(wall);
  const auto& s = r.continuation.summary;
  // Stability by Hill's method (auto: dense QR or shift-invert Arnoldi) on ten points spread
  // along the branch, timed apart: its cost per point is set against the continuation's.
  // Hill works on the full system: beyond a first-order size of 3000 (n = 128, H = 20) one
  // point takes seconds and it is not timed here (NaN in the table).
  double stability = std::nan("");
  if (2 * n * (2 * harmonics + 1) <= 3000) {
    const size_t stride = std::max<size_t>(1, r.continuation.points.size() / 10);
    int timed = 0;
    const auto t1 = Clock::now();
    for (size_t i = 0; i < r.continuation.points.size(); i += stride, ++timed)
      hbtrack::hill_floquet(hbm, r.continuation.points[i].u, r.continuation.points[i].lambda);
    stability = seconds_since(t1) / timed * std::max(1, s.points);  // per point x points
  }
  Row row{n,
          harmonics,
          hbm.basis().samples(),
          hbm.unknowns(),
          s.points,
          s.newton_iterations,
          hbm.condensation_method(),
          hbtrack::to_string(s.stop_reason),
          wall,
          dense_lu_seconds(hbm.unknowns() + 1),
          wall / std::max(1, s.newton_iterations),
          stability,
          breakdown};
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  hbtrack::PhaseTimes::enable(true);
  std::vector<Row> rows;
  const std::vector<int> sizes = quick ? std::vector<int>{2, 8} : std::vector<int>{2, 8, 32, 128};
  const std::vector<int> harmonics = quick ? std::vector<int>{5} : std::vector<int>{5, 10, 20};
  for (int n : sizes)
    for (int h : harmonics) rows.push_back(measure(n, h, "auto"));
  // The number of samples N at one size, then condensation against the full system.
  for (int samples : quick ? std::vector<int>{1024} : std::vector<int>{1024, 4096})
    rows.push_back(measure(quick ? 8 : 32, quick ? 5 : 10, "auto", samples));
  if (!quick)
    for (const char* method : {"schur", "none"}) rows.push_back(measure(32, 10, method));

  std::printf("Dense LU: %s\n\n", hbtrack::DenseLU::backend().c_str());
  std::printf(
      "| n | H | N | condensation | unknowns | points | Newton it. | NFRC wall [s] | per Newton it. [ms] | dense LU [ms] | per it. / LU | "
      "AFT | Jacobian | factorization | rest | Hill per point [ms] | stability / continuation | stop |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows)
    std::printf("| %d | %d | %d | %s | %d | %d | %d | %.4f | %.4f | %.4f | %.1f | %s | %.3f | %.1f | %s |\n", r.n, r.harmonics, r.samples,
                r.condensation.c_str(), r.unknowns, r.points, r.newton, r.wall, 1e3 * r.per_iteration, 1e3 * r.lu, r.per_iteration / r.lu,
                r.breakdown.cells().c_str(), 1e3 * r.stability / std::max(1, r.points), r.stability / r.wall, r.stop.c_str());
  return 0;
}
