#include "node_table.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::cli {

namespace {

[[noreturn]] void fail(const std::string& path, long line, const std::string& rule) {
  throw CaseError(path + ":" + std::to_string(line) + ": " + rule);
}

std::ifstream open_for_reading(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open for reading");
  return in;
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_for_writing(const std::string& path) {
  File file{std::fopen(path.c_str(), "w")};
  if (!file) throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
  return file;
}

void close_checked(File file, const std::string& path) {
  const bool failed = std::ferror(file.get()) != 0;
  if (std::fclose(file.release()) != 0 || failed) throw std::runtime_error(path + ": write failed");
}

bool parse_int(const std::string& text, int& value) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < 1 || v > 2'000'000'000) return false;
  value = static_cast<int>(v);
  return true;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::vector<NodeRecord> read_node_table(const std::string& path) {
  std::ifstream in = open_for_reading(path);
  std::vector<NodeRecord> nodes;
  std::set<int> seen;
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    text = trimmed(text);
    if (text.empty() || text[0] == '#') continue;
    if (line == 1 && !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '+')) continue;  // header
    std::vector<std::string> cells;
    std::stringstream ss(text);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(trimmed(cell));
    if (cells.size() != 4) fail(path, line, "expected 'node,x,y,z' (4 columns), got " + std::to_string(cells.size()));
    NodeRecord node;
    if (!parse_int(cells[0], node.id)) fail(path, line, "node id must be an integer >= 1");
    for (int d = 0; d < 3; ++d) {
      const std::string& cell = cells[static_cast<size_t>(d + 1)];
      char* end = nullptr;
      node.position(d) = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(node.position(d))) fail(path, line, "coordinates must be finite numbers");
    }
    if (!seen.insert(node.id).second) fail(path, line, "node " + std::to_string(node.id) + " listed twice");
    nodes.push_back(node);
  }
  if (nodes.empty()) fail(path, 1, "no nodes");
  return nodes;
}

void write_node_table(const std::string& path, const std::vector<NodeRecord>& nodes) {
  File file = open_for_writing(path);
  std::fprintf(file.get(), "node,x,y,z\n");
  for (const NodeRecord& n : nodes)
    std::fprintf(file.get(), "%d,%.17g,%.17g,%.17g\n", n.id, n.position.x(), n.position.y(), n.position.z());
  close_checked(std::move(file), path);
}

std::vector<int> read_node_list(const std::string& path) {
  std::ifstream in = open_for_reading(path);
  std::vector<int> ids;
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    text = text.substr(0, text.find('#'));
    for (char& c : text)
      if (c == ',') c = ' ';
    std::stringstream ss(text);
    for (std::string word; ss >> word;) {
      int id = 0;
      if (!parse_int(word, id)) fail(path, line, "'" + word + "' is not a node id (an integer >= 1)");
      ids.push_back(id);
    }
  }
  if (ids.empty()) fail(path, 1, "no node ids");
  return ids;
}

void write_node_list(const std::string& path, const std::vector<int>& ids, const std::string& comment) {
  File file = open_for_writing(path);
  std::fprintf(file.get(), "# %s\n", comment.c_str());
  for (int id : ids) std::fprintf(file.get(), "%d\n", id);
  close_checked(std::move(file), path);
}

void write_boundary_nodes(const std::string& path, const std::vector<NodeRecord>& nodes, const std::vector<CylindricalFrame>& frames) {
  File file = open_for_writing(path);
  std::fprintf(file.get(), "node,x,y,z,radius");
  for (const char* axis : {"radial", "circumferential", "axial"})
    for (const char* c : {"x", "y", "z"}) std::fprintf(file.get(), ",%s_%s", axis, c);
  std::fprintf(file.get(), "\n");
  for (size_t j = 0; j < nodes.size(); ++j) {
    const NodeRecord& n = nodes[j];
    std::fprintf(file.get(), "%d,%.17g,%.17g,%.17g,%.17g", n.id, n.position.x(), n.position.y(), n.position.z(), frames[j].radius);
    for (int axis = 0; axis < 3; ++axis)
      for (int c = 0; c < 3; ++c) std::fprintf(file.get(), ",%.17g", frames[j].directions(c, axis) + 0.0);  // + 0.0: no "-0"
    std::fprintf(file.get(), "\n");
  }
  close_checked(std::move(file), path);
}

}  // namespace hbtrack::cli
