#include "hbtrack/io/calculix_input_nodes.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unordered_map>

namespace hbtrack {

namespace {

namespace fs = std::filesystem;

// Includes nest this deep at most: a deck that includes itself fails instead of recursing.
constexpr int kMaxIncludeDepth = 16;

[[noreturn]] void fail(const std::string& path, long line, const std::string& rule) {
  throw std::runtime_error(path + ": line " + std::to_string(line) + ": " + rule);
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

std::vector<std::string> comma_fields(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(trimmed(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  while (!out.empty() && out.back().empty()) out.pop_back();  // a trailing comma ends a line in many decks
  return out;
}

// A keyword line "*NAME, KEY=VALUE, ...": the upper-cased name and parameters (keys upper-cased,
// values as written, since an INPUT= file name is case-sensitive).
struct Keyword {
  std::string name;
  std::unordered_map<std::string, std::string> parameters;
};

Keyword parse_keyword(const std::string& line) {
  const std::vector<std::string> parts = comma_fields(line);
  Keyword k;
  k.name = upper(parts.empty() ? line : parts[0]);
  for (size_t i = 1; i < parts.size(); ++i) {
    const size_t equals = parts[i].find('=');
    const std::string key = upper(trimmed(parts[i].substr(0, equals)));
    k.parameters[key] = equals == std::string::npos ? "" : trimmed(parts[i].substr(equals + 1));
  }
  return k;
}

bool parse_number(const std::string& text, double& value) {
  std::string_view v(text);
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);  // from_chars takes no '+'
  const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), value);
  return error == std::errc() && end == v.data() + v.size() && std::isfinite(value);
}

struct Where {
  std::string path;
  long line = 0;
};

class NodeDeckReader {
 public:
  std::vector<CalculixNode> nodes;

  void read(const std::string& path, int depth) {
    std::ifstream in(path);
    if (!in) fail(path, 0, "cannot open for reading");
    bool in_node_block = false;
    std::string text;
    long line = 0;
    while (std::getline(in, text)) {
      ++line;
      text = trimmed(text);
      if (text.empty() || text.rfind("**", 0) == 0) continue;
      if (text[0] == '*') {
        in_node_block = keyword(parse_keyword(text), path, line, depth);
        continue;
      }
      if (in_node_block) node_line(text, path, line);
    }
  }

 private:
  std::unordered_map<int, Where> defined_at_;

  // Acts on a keyword line; true when the data lines that follow are nodes.
  bool keyword(const Keyword& k, const std::string& path, long line, int depth) {
    if (k.name == "*TRANSFORM")
      fail(path, line, "*TRANSFORM turns the dofs of its nodes into a local frame; reduce needs the matrices in global x, y, z");
    if (k.name == "*INCLUDE") {
      const auto input = k.parameters.find("INPUT");
      if (input == k.parameters.end() || input->second.empty()) fail(path, line, "*INCLUDE needs INPUT=FILE");
      if (depth + 1 >= kMaxIncludeDepth)
        fail(path, line, "*INCLUDE nested more than " + std::to_string(kMaxIncludeDepth) + " deep (does a file include itself?)");
      const fs::path beside = fs::path(path).parent_path() / input->second;
      const std::string included = fs::exists(beside) ? beside.string() : input->second;
      // A device or a pipe (/dev/zero, /dev/stdin) would be read forever.
      if (!fs::is_regular_file(included)) fail(path, line, "*INCLUDE, INPUT=" + input->second + ": not a readable regular file");
      read(included, depth + 1);
      return false;
    }
    if (k.name != "*NODE") return false;
    if (const auto system = k.parameters.find("SYSTEM"); system != k.parameters.end() && upper(system->second) != "R")
      fail(path, line, "*NODE, SYSTEM=" + system->second + ": only rectangular coordinates (SYSTEM=R, the default) are read");
    return true;
  }

  void node_line(const std::string& text, const std::string& path, long line) {
    const std::vector<std::string> f = comma_fields(text);
    if (f.empty() || f.size() > 4) fail(path, line, "a *NODE line is 'id, x, y, z', got " + std::to_string(f.size()) + " fields");
    CalculixNode node;
    const auto [end, error] = std::from_chars(f[0].data(), f[0].data() + f[0].size(), node.id);
    if (error != std::errc() || end != f[0].data() + f[0].size() || node.id < 1)
      fail(path, line, "node id '" + f[0] + "' must be an integer >= 1");
    for (size_t d = 1; d < f.size(); ++d)
      if (!parse_number(f[d], node.position(static_cast<Eigen::Index>(d - 1))))
        fail(path, line,
             "coordinate " + std::string(1, "xyz"[d - 1]) + " of node " + std::to_string(node.id) + " must be a finite number, got '" +
                 f[d] + "'");
    if (const auto seen = defined_at_.find(node.id); seen != defined_at_.end())
      fail(path, line,
           "node " + std::to_string(node.id) + " is already defined at " + seen->second.path + ": line " +
               std::to_string(seen->second.line));
    defined_at_.emplace(node.id, Where{path, line});
    nodes.push_back(node);
  }
};

}  // namespace

std::vector<CalculixNode> read_calculix_input_nodes(const std::string& inp_path) {
  NodeDeckReader reader;
  reader.read(inp_path, 0);
  if (reader.nodes.empty()) fail(inp_path, 0, "no *NODE block: the deck defines no node");
  return reader.nodes;
}

}  // namespace hbtrack
