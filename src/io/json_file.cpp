#include "hbtrack/io/json_file.hpp"

#include <string>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/io/input_file.hpp"

namespace hbtrack {

void check_json_nesting(std::string_view text, const std::string& source) {
  int depth = 0;
  long line = 1;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '\n') ++line;
    if (in_string) {
      if (ch == '\\')
        ++i;  // an escaped quote or backslash
      else if (ch == '"')
        in_string = false;
    } else if (ch == '"') {
      in_string = true;
    } else if (ch == '[' || ch == '{') {
      if (++depth > kMaxJsonNesting)
        throw CaseError(source + ":" + std::to_string(line) + ": arrays or objects nested deeper than " + std::to_string(kMaxJsonNesting) +
                        " levels");
    } else if ((ch == ']' || ch == '}') && depth > 0) {
      --depth;
    }
  }
}

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  const std::string text = read_bounded_file(path, kMaxJsonFileBytes, what);
  check_json_nesting(text, path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 1, column 5: ...": the library's tag dropped.
    std::string why = e.what();
    if (const auto tag = why.find("] "); why.rfind("[json.exception", 0) == 0 && tag != std::string::npos) why = why.substr(tag + 2);
    throw CaseError(path + ": not valid JSON (" + why + ")");
  }
}

}  // namespace hbtrack
