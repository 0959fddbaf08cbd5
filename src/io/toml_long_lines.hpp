#pragma once
// toml11 3.7 looks along a value's whole line for the comments around it as it parses each
// value, so one line of n values costs n times its length: 20 000 values on each of six lines
// took 10 s of CPU. Long lines are broken after the commas of their arrays (TOML allows a
// newline there, also in an array inside an inline table) before the parse, and the messages
// name the lines of the file as written.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace hbtrack {

// Lines up to this length are parsed as written: a case file's matrix rows and lists are far
// shorter, and toml11 takes microseconds over such a line.
inline constexpr std::size_t kLongTomlLineBytes = 4096;

// The file's line of each line of a text made from it by inserting newlines.
struct LineMap {
  std::vector<long> original_line;  // line k of the text is the file's original_line[k - 1]; empty: the same lines
  long original(long line) const {
    if (original_line.empty() || line < 1 || line > static_cast<long>(original_line.size())) return line;
    return original_line[static_cast<std::size_t>(line - 1)];
  }
};

struct TomlLines {
  std::string text;  // what the parser reads
  LineMap lines;
};

// `text` with a newline after every comma of an array (the innermost bracket open is a `[`) on
// a line longer than `max_line_bytes`; strings and comments are left as they are.
TomlLines break_long_toml_lines(std::string_view text, std::size_t max_line_bytes = kLongTomlLineBytes);

}  // namespace hbtrack
