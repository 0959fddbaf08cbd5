#include "toml_long_lines.hpp"

#include <algorithm>

#include "toml_scan.hpp"

namespace hbtrack {

TomlLines break_long_toml_lines(std::string_view text, std::size_t max_line_bytes) {
  std::vector<bool> long_line;  // of each line, 1-based at index - 1
  bool any_long = false;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    long_line.push_back(end - start > max_line_bytes);
    any_long = any_long || long_line.back();
    start = end + 1;
  }
  if (!any_long) return {std::string(text), {}};

  std::vector<std::size_t> breaks;  // after these commas
  std::string open;                 // the brackets open at each point, innermost last
  scan_toml_code(text, [&](std::size_t i, char ch, long line) {
    if (ch == '[' || ch == '{')
      open.push_back(ch);
    else if ((ch == ']' || ch == '}') && !open.empty())
      open.pop_back();
    else if (ch == ',' && !open.empty() && open.back() == '[' && long_line[static_cast<std::size_t>(line - 1)] && i + 1 < text.size() &&
             text[i + 1] != '\n' && text[i + 1] != '\r')  // not at a line's end already (CR LF)
      breaks.push_back(i);
  });

  TomlLines out;
  out.text.reserve(text.size() + breaks.size());
  long line = 1;
  out.lines.original_line.push_back(line);
  std::size_t next_break = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    out.text.push_back(text[i]);
    if (text[i] == '\n') out.lines.original_line.push_back(++line);
    if (next_break < breaks.size() && breaks[next_break] == i) {
      out.text.push_back('\n');
      out.lines.original_line.push_back(line);
      ++next_break;
    }
  }
  return out;
}

}  // namespace hbtrack
