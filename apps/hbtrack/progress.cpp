#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "hbtrack/io/case_file.hpp"  // CaseError

namespace hbtrack::cli {

std::string duration_text(double seconds) {
  char buf[32];
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, s / 60 % 60);
  else if (s >= 60)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%lds", s);
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
    std::snprintf(buf, sizeof buf, " %5.1f %%  %-14s", 100 * s.fraction, time_left_text(s.fraction, s.elapsed_s).c_str());
    line += buf;
  }
  if (!s.output.empty()) {
    std::snprintf(buf, sizeof buf, "  max_%s %-12.5g", s.output.c_str(), s.output_max);
    line += buf;
  }
  return line;
}

std::string time_left_text(double fraction, double elapsed_s) {
  // The pace so far, extrapolated: rough near a resonance (or a cusp), where the steps shorten.
  if (!(fraction > 0.01 && fraction < 1)) return "";
  return "~" + duration_text(elapsed_s * (1 - fraction) / fraction) + " left";
}

std::string relay_line(const ProgressState& s) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "%d %.6f %.3f\n", s.index, s.fraction, s.elapsed_s);
  return buf;
}

bool parse_relay_line(const std::string& line, ProgressState& s) {
  int index = 0, consumed = 0;
  double fraction = 0, elapsed = 0;
  if (std::sscanf(line.c_str(), "%d %lf %lf%n", &index, &fraction, &elapsed, &consumed) != 3) return false;
  if (line.find_first_not_of(" \n", static_cast<size_t>(consumed)) != std::string::npos) return false;
  s.index = index;
  s.fraction = fraction;
  s.elapsed_s = elapsed;
  return true;
}

double progress_line_interval_s() {
  constexpr double kDefault = 5;  // a log file a reader scrolls: a line every few seconds
  const char* text = std::getenv("HBTRACK_PROGRESS_INTERVAL");
  if (!text) return kDefault;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  return end != text && *end == '\0' && seconds > 0 && std::isfinite(seconds) ? seconds : kDefault;
}

ProgressStyle progress_style(bool quiet) {
  return quiet ? ProgressStyle::none : isatty(STDERR_FILENO) ? ProgressStyle::terminal : ProgressStyle::lines;
}

Progress::Progress(bool quiet) : style_(progress_style(quiet)) {
  last_line_ = t0_;  // the first line after one interval: a short run writes none
}

Progress::Progress(bool quiet, double range_start, double range_end) : Progress(quiet) {
  has_range_ = true;
  coverage_ = Coverage::one_way(range_start, range_end);
}

Progress::Progress(bool quiet, const std::string& parameter, double lo, double hi, double from) : Progress(quiet) {
  has_range_ = true;
  coverage_ = Coverage::two_legs(lo, hi, from);
  parameter_ = parameter;
}

Progress::~Progress() {
  finish();
  if (relay_) std::fclose(relay_);
}

void Progress::relay_to(const std::string& path) {
  if (path.empty()) return;
  relay_ = std::fopen(path.c_str(), "a");
  if (!relay_) throw CaseError("--progress-file: cannot open " + path + " for writing");
}

void Progress::finish() {
  if (shown_) std::fprintf(stderr, "\n");
  shown_ = false;
  if (lines_written_ > 0 && !unwritten_.empty()) write_line(unwritten_);
  unwritten_.clear();
}

void Progress::write_line(const std::string& text) {
  // The terminal's indent and padding are of no use in a log.
  const size_t first = text.find_first_not_of(' ');
  const std::string line = first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(' ') + 1 - first);
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
  ++lines_written_;
}

void Progress::update(int index, double omega, const RecordedPoint& p, const std::vector<OutputDof>& outputs) {
  if (style_ == ProgressStyle::none && !relay_) return;
  ProgressState s;
  s.index = index;
  s.omega = omega;
  show(s, omega, 1, p, outputs);
}

void Progress::update(int index, double omega, double parameter_value, int leg, const RecordedPoint& p,
                      const std::vector<OutputDof>& outputs) {
  if (style_ == ProgressStyle::none && !relay_) return;
  ProgressState s;
  s.index = index;
  s.omega = omega;
  s.parameter = parameter_;
  s.parameter_value = parameter_value;
  show(s, parameter_value, leg, p, outputs);
}

void Progress::show(ProgressState s, double position, int leg, const RecordedPoint& p, const std::vector<OutputDof>& outputs) {
  const auto now = std::chrono::steady_clock::now();
  s.elapsed_s = std::chrono::duration<double>(now - t0_).count();
  if (has_range_) s.fraction = coverage_.add(position, leg);
  // A line per point would be thousands on a long run: a few a second are all a reader shows.
  if (relay_ && now - last_relayed_ >= std::chrono::milliseconds(100)) {
    std::fputs(relay_line(s).c_str(), relay_);
    std::fflush(relay_);
    last_relayed_ = now;
  }
  if (style_ == ProgressStyle::none) return;
  if (!outputs.empty() && !p.outputs.empty()) {
    s.output = outputs[0].name;
    s.output_max = p.outputs[0].max;
  }
  if (style_ == ProgressStyle::lines) {
    unwritten_ = progress_text(s);
    if (std::chrono::duration<double>(now - last_line_).count() >= progress_line_interval_s()) {
      write_line(unwritten_);
      unwritten_.clear();
      last_line_ = now;
    }
    return;
  }
  std::fprintf(stderr, "\r%s", progress_text(s).c_str());
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace hbtrack::cli
