#include "hbtrack/io/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack {

namespace fs = std::filesystem;

void require_regular_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw CaseError(path + ": file does not exist");
  if (fs::is_directory(status)) throw CaseError(path + ": is a directory, expected " + what);
  if (!fs::is_regular_file(status)) throw CaseError(path + ": is not a regular file (a device, pipe or socket), expected " + what);
}

std::string read_bounded_file(const std::string& path, std::size_t max_bytes, const std::string& what) {
  require_regular_file(path, what);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw CaseError(path + ": cannot read: " + std::strerror(errno));
  // In chunks, stopping one byte past the limit: the file may grow after the check.
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= max_bytes && file.read(chunk, sizeof chunk).gcount() > 0)
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
  if (file.bad()) throw CaseError(path + ": cannot read: " + std::strerror(errno));
  if (text.size() > max_bytes)
    throw CaseError(path + ": larger than " +
                    (max_bytes >= (1u << 20) ? std::to_string(max_bytes >> 20) + " MiB" : std::to_string(max_bytes) + " bytes") +
                    ", the limit for " + what);
  return text;
}

void check_toml_nesting(std::string_view text, const std::string& source) {
  enum class State { code, comment, basic, literal, multiline_basic, multiline_literal };
  State state = State::code;
  int depth = 0;
  long line = 1;
  const auto starts = [&](std::size_t i, std::string_view token) { return text.substr(i, token.size()) == token; };
  // A multi-line string may end with up to two quotes of content before its closing three.
  const auto closing_quotes = [&](std::size_t i, char quote) {
    std::size_t n = 0;
    while (n < 5 && i + n < text.size() && text[i + n] == quote) ++n;
    return n;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n') {
      ++line;
      // A single-line string or a comment ends at the line's end (an unterminated string is
      // the parser's error to report).
      if (state == State::comment || state == State::basic || state == State::literal) state = State::code;
      continue;
    }
    switch (state) {
      case State::code:
        if (ch == '#')
          state = State::comment;
        else if (starts(i, "\"\"\""))
          state = State::multiline_basic, i += 2;
        else if (starts(i, "'''"))
          state = State::multiline_literal, i += 2;
        else if (ch == '"')
          state = State::basic;
        else if (ch == '\'')
          state = State::literal;
        else if (ch == '[' || ch == '{') {
          if (++depth > kMaxTomlNesting)
            throw CaseError(source + ":" + std::to_string(line) + ": arrays or inline tables nested deeper than " +
                            std::to_string(kMaxTomlNesting) + " levels");
        } else if ((ch == ']' || ch == '}') && depth > 0) {
          --depth;
        }
        break;
      case State::comment:
        break;
      case State::basic:
        if (ch == '\\')
          ++i;  // an escaped quote or backslash
        else if (ch == '"')
          state = State::code;
        break;
      case State::literal:
        if (ch == '\'') state = State::code;
        break;
      case State::multiline_basic:
        if (ch == '\\') {
          if (i + 1 < text.size() && text[i + 1] == '\n') ++line;
          ++i;
        } else if (starts(i, "\"\"\"")) {
          state = State::code, i += closing_quotes(i, '"') - 1;
        }
        break;
      case State::multiline_literal:
        if (starts(i, "'''")) state = State::code, i += closing_quotes(i, '\'') - 1;
        break;
    }
  }
}

}  // namespace hbtrack
