// One periodic solution and the NFRC of a case file through the C++ library (docs/cpp-api.md).
#include <cstdio>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"

int main() {
  // The case file as the CLI reads it, with --set's overrides.
  const hbtrack::CaseDefinition c = hbtrack::load_case("examples/duffing.toml", {"amplitude=1.0"});
  hbtrack::HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);

  // One periodic solution at omega = 1.2 rad/s (hbtrack solve --omega 1.2): Newton from the
  // linear solution, the case's tolerance.
  const auto& co = c.nfrc.continuation;
  const hbtrack::FixedFrequencySolution one = hbtrack::solve_at_frequency(hbm, 1.2, c.outputs, co.tolerance, 4 * co.max_iterations);
  std::printf("solve: converged %d in %d iterations, max_%s %.6g\n", one.converged, one.newton_iterations, c.outputs[0].name.c_str(),
              one.recorded.outputs[0].max);

  // The NFRC over the case's range (hbtrack frc), the observer called at every accepted point.
  int seen = 0;
  const hbtrack::NfrcResult nfrc =
      hbtrack::compute_nfrc(hbm, c.nfrc, c.outputs, [&](const hbtrack::BranchPoint&, const hbtrack::RecordedPoint&, int) {
        ++seen;
        return true;  // false stops the continuation there
      });
  std::printf("frc: %zu points (%d observed), %s\n", nfrc.recorded.size(), seen,
              hbtrack::to_string(nfrc.continuation.summary.stop_reason).c_str());
  for (const hbtrack::SpecialPoint& sp : nfrc.continuation.special_points)
    std::printf("  %s at omega %.6f\n", hbtrack::to_string(sp.type).c_str(), sp.lambda);
  return nfrc.continuation.success() ? 0 : 1;
}
