#include "hbtrack/io/calculix_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

namespace hbtrack {

namespace {

// A matrix is sized by its largest index (or the dof map): one line "20000000 1 6" would
// otherwise allocate index arrays for 20 million rows. A million dofs is far beyond any model
// this tool reduces (the blade has a few thousand).
constexpr int kMaxDofs = 1'000'000;

[[noreturn]] void fail(const std::string& path, long line, const std::string& rule) {
  throw std::runtime_error(path + ": line " + std::to_string(line) + ": " + rule);
}

std::ifstream open_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": line 0: cannot open for reading");
  return in;
}

// Whitespace-separated fields of a line.
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool parse_int(std::string_view text, int& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

bool parse_finite(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // from_chars takes no '+'
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

}  // namespace

std::vector<CalculixDof> read_calculix_dof_map(const std::string& path) {
  std::ifstream in = open_text(path);
  std::vector<CalculixDof> dofs;
  std::unordered_map<std::int64_t, long> first_line;  // node * 8 + direction -> line
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto f = fields(text);
    if (f.empty()) continue;
    const size_t dot = f[0].find('.');
    CalculixDof dof;
    if (f.size() != 1 || dot == std::string_view::npos || !parse_int(f[0].substr(0, dot), dof.node) ||
        !parse_int(f[0].substr(dot + 1), dof.direction))
      fail(path, line, "expected one 'node.direction' entry, e.g. 12.3");
    if (dof.node < 1) fail(path, line, "node number must be >= 1");
    if (dof.direction < 0 || dof.direction > 6) fail(path, line, "direction must be 0 to 6 (1-3: x, y, z)");
    const std::int64_t key = std::int64_t{dof.node} * 8 + dof.direction;
    if (const auto seen = first_line.find(key); seen != first_line.end())
      fail(path, line,
           "dof " + std::to_string(dof.node) + "." + std::to_string(dof.direction) + " already listed on line " +
               std::to_string(seen->second));
    first_line.emplace(key, line);
    dofs.push_back(dof);
  }
  if (dofs.empty()) fail(path, 1, "no dofs (empty file)");
  return dofs;
}

Eigen::SparseMatrix<double> read_calculix_matrix(const std::string& path, int rows) {
  std::ifstream in = open_text(path);
  std::vector<Eigen::Triplet<double>> entries;
  std::unordered_map<std::int64_t, long> first_line;  // row * 2^31 + column -> line
  int largest = 0, triangle = 0;                      // +1 upper (row < column), -1 lower
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto f = fields(text);
    if (f.empty()) continue;
    int row = 0, column = 0;
    double value = 0;
    if (f.size() != 3) fail(path, line, "expected 'row column value'");
    if (!parse_int(f[0], row) || !parse_int(f[1], column) || row < 1 || column < 1)
      fail(path, line, "row and column must be integers >= 1");
    if (!parse_finite(f[2], value)) fail(path, line, "value must be a finite number");
    if (std::max(row, column) > kMaxDofs)
      fail(path, line, "index " + std::to_string(std::max(row, column)) + " exceeds the limit of " + std::to_string(kMaxDofs) + " dofs");
    if (rows >= 0 && std::max(row, column) > rows)
      fail(path, line, "index " + std::to_string(std::max(row, column)) + " exceeds the " + std::to_string(rows) + " dofs of the dof map");
    if (row != column) {
      const int side = row < column ? 1 : -1;
      if (triangle == 0) triangle = side;
      if (side != triangle) fail(path, line, "entries on both sides of the diagonal: expected one triangle of a symmetric matrix");
    }
    const std::int64_t key = (std::int64_t{row} << 31) + column;
    if (const auto seen = first_line.find(key); seen != first_line.end())
      fail(path, line,
           "duplicate entry (" + std::to_string(row) + ", " + std::to_string(column) + "), first on line " + std::to_string(seen->second));
    first_line.emplace(key, line);
    largest = std::max({largest, row, column});
    entries.emplace_back(row - 1, column - 1, value);
    if (row != column) entries.emplace_back(column - 1, row - 1, value);
  }
  if (entries.empty()) fail(path, 1, "no matrix entries (empty file)");
  const int size = rows >= 0 ? rows : largest;
  Eigen::SparseMatrix<double> matrix(size, size);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

CalculixMatrices read_calculix_matrices(const std::string& jobname) {
  CalculixMatrices out;
  out.dofs = read_calculix_dof_map(jobname + ".dof");
  const int rows = static_cast<int>(out.dofs.size());
  out.stiffness = read_calculix_matrix(jobname + ".sti", rows);
  out.mass = read_calculix_matrix(jobname + ".mas", rows);
  return out;
}

}  // namespace hbtrack
