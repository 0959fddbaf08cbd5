#include "resume_command.hpp"

#include <vector>

namespace hbtrack::cli {

namespace {
std::vector<std::string>& typed_words() {
  static std::vector<std::string> words;
  return words;
}

std::string joined(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + shell_quoted(w);
  return line;
}
}  // namespace

void remember_command_line(int argc, const char* const* argv) { typed_words().assign(argv, argv + argc); }

std::string typed_command() { return joined(typed_words()); }

std::string resume_command(const std::string& dir) {
  const std::vector<std::string>& typed = typed_words();
  std::vector<std::string> kept;
  for (size_t i = 0; i < typed.size(); ++i) {
    const std::string& w = typed[i];
    // The folder is --resume's own; CLI11 takes "-o DIR", "-oDIR", "--output DIR", "--output=DIR".
    if (w == "-o" || w == "--output" || w == "--resume") {
      ++i;
      continue;
    }
    if ((w.rfind("-o", 0) == 0 && w.rfind("--", 0) != 0) || w.rfind("--output=", 0) == 0 || w.rfind("--resume=", 0) == 0) continue;
    kept.push_back(w);
  }
  kept.insert(kept.end(), {"--resume", dir});
  return joined(kept);
}

std::string resume_advice(const std::string& stop_reason, const std::string& command) {
  if (stop_reason != "interrupted" && stop_reason != "time_limit") return "";
  return stop_reason + ": resume with: " + command;
}

std::string shell_quoted(const std::string& word) {
  constexpr const char* kPlain = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=.,:/@%";
  if (!word.empty() && word.find_first_not_of(kPlain) == std::string::npos) return word;
  std::string quoted = "'";
  for (const char ch : word) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

}  // namespace hbtrack::cli
