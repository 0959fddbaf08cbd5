#include "step_progress.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "progress.hpp"

namespace hbtrack::cli {

namespace {
// Often enough to follow a step, rarely enough to cost nothing (a few small reads).
constexpr auto kPoll = std::chrono::milliseconds(250);

// The end of a file: its last lines, however long the step has been writing it.
std::string read_tail(const std::string& path) {
  constexpr std::streamoff kTail = 256;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  in.seekg(size > kTail ? size - kTail : 0);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

std::string step_progress_text(const std::string& step, const std::string& file_text) {
  // The last complete line: a step may be writing the next one as this reads.
  const size_t end = file_text.rfind('\n');
  if (end == std::string::npos || end == 0) return "";
  const size_t previous = file_text.rfind('\n', end - 1);
  const size_t start = previous == std::string::npos ? 0 : previous + 1;
  const std::string line = file_text.substr(start, end - start);
  ProgressState s;
  if (!parse_relay_line(line, s)) return "";
  char buf[64];
  if (s.fraction < 0) {
    std::snprintf(buf, sizeof buf, "point %d", s.index);
    return step + " " + buf;
  }
  std::snprintf(buf, sizeof buf, "%.1f %%", 100 * s.fraction);
  const std::string left = time_left_text(s.fraction, s.elapsed_s);
  return step + " " + buf + (left.empty() ? "" : " " + left);
}

std::string step_end_line(const std::string& step, int exit_code, double step_s, size_t ended, size_t steps, double stage_elapsed_s) {
  const std::string left = steps > 0 ? time_left_text(static_cast<double>(ended) / static_cast<double>(steps), stage_elapsed_s) : "";
  char line[320];
  std::snprintf(line, sizeof line, "study:   %-26s exit %d, %.1f s (step %zu of %zu%s%s)", step.c_str(), exit_code, step_s, ended, steps,
                left.empty() ? "" : ", stage ", left.c_str());
  return line;
}

StepProgressRelay::StepProgressRelay(ProgressStyle style) : style_(style), enabled_(style != ProgressStyle::none) {
  if (enabled_) thread_ = std::thread([this] { loop(); });
}

StepProgressRelay::~StepProgressRelay() {
  if (!enabled_) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
  clear_locked();
}

void StepProgressRelay::watch(const std::string& step, const std::string& file) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  files_[step] = file;
}

void StepProgressRelay::forget(const std::string& step) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  if (const auto it = files_.find(step); it != files_.end()) {
    // Its last progress shows once more on a terminal: a step shorter than the poll would
    // otherwise never show (in a log its end line follows).
    const std::string text = style_ == ProgressStyle::terminal ? step_progress_text(step, read_tail(it->second)) : "";
    if (!text.empty()) draw_locked("study:   " + text);
    std::error_code ignored;
    std::filesystem::remove(it->second, ignored);
    files_.erase(it);
  }
}

void StepProgressRelay::say(const std::string& line) {
  std::lock_guard lock(mutex_);
  clear_locked();
  std::fprintf(stderr, "%s\n", line.c_str());
}

void StepProgressRelay::clear_locked() {
  if (shown_ == 0) return;
  std::fprintf(stderr, "\r%s\r", std::string(shown_, ' ').c_str());
  shown_ = 0;
}

void StepProgressRelay::loop() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, kPoll, [this] { return stopping_; })) {
    std::string line;
    for (const auto& [step, file] : files_)
      if (const std::string text = step_progress_text(step, read_tail(file)); !text.empty()) line += (line.empty() ? "" : ", ") + text;
    if (!line.empty()) draw_locked("study:   " + line);
  }
}

void StepProgressRelay::draw_locked(std::string line) {
  if (style_ == ProgressStyle::lines) {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_line_).count() < progress_line_interval_s()) return;
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
    last_line_ = now;
    return;
  }
  // Padded over a longer line before it; the terminal's width is not known, so it may wrap.
  const size_t width = line.size();
  if (width < shown_) line += std::string(shown_ - width, ' ');
  std::fprintf(stderr, "\r%s", line.c_str());
  std::fflush(stderr);
  shown_ = width;
}

}  // namespace hbtrack::cli
