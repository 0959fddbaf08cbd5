#pragma once
// One pass over TOML text that tells code from strings and comments, for what is checked or
// changed before toml11 parses it (nesting depth: input_file.cpp; long lines: toml_long_lines).
#include <cstddef>
#include <string_view>

namespace hbtrack {

// Calls visit(i, ch, line) for every character of `text` outside strings and comments but for
// newlines (line: 1-based, of character i). An unterminated string ends at its line's end, as
// far as this scan goes (the parser reports it).
template <class Visit>
void scan_toml_code(std::string_view text, Visit&& visit) {
  enum class State { code, comment, basic, literal, multiline_basic, multiline_literal };
  State state = State::code;
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
      // A single-line string or a comment ends at the line's end.
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
        else
          visit(i, ch, line);
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
