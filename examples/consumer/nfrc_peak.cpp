// The NFRC of a case file computed through the installed library: prints the number of points,
// the peak of the first output and the limit points found. Exit 1 when the continuation fails.
#include <cstdio>
#include <exception>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: nfrc_peak CASE.toml\n");
    return 2;
  }
  try {
    const hbtrack::CaseDefinition c = hbtrack::load_case(argv[1]);
    hbtrack::HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
    const hbtrack::NfrcResult r = hbtrack::compute_nfrc(hbm, c.nfrc, c.outputs);
    double peak = 0, omega_at_peak = 0;
    for (const hbtrack::RecordedPoint& p : r.recorded)
      if (!p.outputs.empty() && p.outputs[0].max > peak) peak = p.outputs[0].max, omega_at_peak = p.omega;
    int limit_points = 0;
    for (const auto& sp : r.continuation.special_points) limit_points += sp.type == hbtrack::SpecialPointType::limit_point;
    std::printf("points %zu peak %.6g at omega %.6g limit_points %d stop %s\n", r.recorded.size(), peak, omega_at_peak, limit_points,
                hbtrack::to_string(r.continuation.summary.stop_reason).c_str());
    return r.continuation.success() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nfrc_peak: %s\n", e.what());
    return 2;
  }
}
