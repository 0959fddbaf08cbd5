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

std::string progress_text(const ProgressState& s) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "  point %5d  omega %-12.6g", s.index, s.omega);
  std::string line = buf;
  if (!s.parameter.empty()) {
    std::snprintf(buf, sizeof buf, "  %s %-12.6g", s.parameter.c_str(), s.parameter_value);
    line += buf;
  }
  if (s.fraction >= 0) {
    // The pace so far, extrapolated: rough near a resonance (or a cusp), where the steps shorten.
    const std::string left =
        s.fraction > 0.01 && s.fraction < 1 ? "~" + duration_text(s.elapsed_s * (1 - s.fraction) / s.fraction) + " left" : "";
    std::snprintf(buf, sizeof buf, " %5.1f %%  %-14s", 100 * s.fraction, left.c_str());
    line += buf;
  }
  if (!s.output.empty()) {
    std::snprintf(buf, sizeof buf, "  max_%s %-12.5g", s.output.c_str(), s.output_max);
    line += buf;
  }
  return line;
}

Progress::Progress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}

Progress::Progress(bool quiet, double range_start, double range_end) : Progress(quiet) {
  has_range_ = true;
  coverage_ = Coverage::one_way(range_start, range_end);
}

Progress::Progress(bool quiet, const std::string& parameter, double lo, double hi, double from) : Progress(quiet) {
  has_range_ = true;
  coverage_ = Coverage::two_legs(lo, hi, from);
  parameter_ = parameter;
}

Progress::~Progress() { finish(); }

void Progress::finish() {
  if (shown_) std::fprintf(stderr, "\n");
  shown_ = false;
}

void Progress::update(int index, double omega, const RecordedPoint& p, const std::vector<OutputDof>& outputs) {
  if (!enabled_) return;
  ProgressState s;
  s.index = index;
  s.omega = omega;
  show(s, omega, 1, p, outputs);
}

void Progress::update(int index, double omega, double parameter_value, int leg, const RecordedPoint& p,
                      const std::vector<OutputDof>& outputs) {
  if (!enabled_) return;
  ProgressState s;
  s.index = index;
  s.omega = omega;
  s.parameter = parameter_;
  s.parameter_value = parameter_value;
  show(s, parameter_value, leg, p, outputs);
}

void Progress::show(ProgressState s, double position, int leg, const RecordedPoint& p, const std::vector<OutputDof>& outputs) {
  if (has_range_) {
    s.fraction = coverage_.add(position, leg);
    s.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  if (!outputs.empty() && !p.outputs.empty()) {
    s.output = outputs[0].name;
    s.output_max = p.outputs[0].max;
  }
  std::fprintf(stderr, "\r%s", progress_text(s).c_str());
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace hbtrack::cli
