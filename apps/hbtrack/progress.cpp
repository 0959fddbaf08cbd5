#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hbtrack::cli {

std::string duration_text(double seconds) {
  char buf[32];
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, s / 60 % 60);
  else if (s >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%lds", s);
  return buf;
}

double covered_fraction(double value, double start, double end) {
  const double span = end - start;
  if (span == 0 || !std::isfinite(value)) return 0;
  return std::clamp((value - start) / span, 0.0, 1.0);
}

Progress::Progress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}

Progress::Progress(bool quiet, double range_start, double range_end) : Progress(quiet) {
  has_range_ = true;
  start_ = range_start;
  end_ = range_end;
}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\n");
}

void Progress::update(int index, double omega, const RecordedPoint& p, const std::vector<OutputDof>& outputs) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r  point %5d  omega %-12.6g", index, omega);
  if (has_range_) {
    furthest_ = std::max(furthest_, covered_fraction(omega, start_, end_));
    std::fprintf(stderr, " %5.1f %%", 100 * furthest_);
    // The pace so far, extrapolated: rough near a resonance, where the steps shorten.
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const std::string left = furthest_ > 0.01 && furthest_ < 1 ? "~" + duration_text(elapsed * (1 - furthest_) / furthest_) + " left" : "";
    std::fprintf(stderr, "  %-14s", left.c_str());
  }
  if (!outputs.empty() && !p.outputs.empty()) std::fprintf(stderr, "  max_%s %-12.5g", outputs[0].name.c_str(), p.outputs[0].max);
  std::fflush(stderr);
}

}  // namespace hbtrack::cli
