#include "hbtrack/io/blade_sections_reader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <vector>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack {

namespace {

constexpr const char* kHeader = "surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m";
constexpr const char* kColumns[] = {"surface", "point", "axial_m", "radius_m", "rtheta_suction_m", "tangential_thickness_m"};
// Far above any blade (rotor 67: 14 x 70 rows) and small enough that a wrong file fails fast.
constexpr long kMaxRows = 1'000'000;

[[noreturn]] void fail(const std::string& path, long line, const std::string& what) {
  throw CaseError(path + ":" + std::to_string(line) + ": " + what);
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

double parse_number(const std::string& text, const std::string& path, long line, const char* column) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  // ERANGE also flags a subnormal such as 1e-310, which is a number: only an overflow is not.
  if (text.empty() || *end != '\0' || !std::isfinite(v)) fail(path, line, std::string(column) + ": '" + text + "' is not a finite number");
  return v;
}

int parse_index(const std::string& text, const std::string& path, long line, const char* column) {
  const double v = parse_number(text, path, line, column);
  if (v != std::floor(v) || v < 1 || v > 1e6) fail(path, line, std::string(column) + ": must be a whole number >= 1");
  return static_cast<int>(v);
}

}  // namespace

BladeSections read_blade_sections(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw CaseError(path + ": cannot open for reading");
  if (!S_ISREG(info.st_mode)) throw CaseError(path + ": not a regular file");
  std::ifstream in(path);
  if (!in) throw CaseError(path + ": cannot open for reading");
  BladeSections sections;
  bool header_seen = false;
  long line = 0, rows = 0;
  std::string text;
  while (std::getline(in, text)) {
    ++line;
    text = trimmed(text);
    if (text.empty()) continue;
    if (text[0] == '#') {
      const auto equals = text.find('=');
      if (equals != std::string::npos && trimmed(text.substr(1, equals - 1)) == "blade_count") {
        // A second line would silently replace the first.
        if (sections.blade_count != 0) fail(path, line, "blade_count: given twice");
        sections.blade_count = parse_index(trimmed(text.substr(equals + 1)), path, line, "blade_count");
        if (sections.blade_count > kMaxBladeCount) fail(path, line, "blade_count: must be <= " + std::to_string(kMaxBladeCount));
      }
      continue;
    }
    if (!header_seen) {
      if (text != kHeader) fail(path, line, std::string("header: expected '") + kHeader + "'");
      header_seen = true;
      continue;
    }
    if (++rows > kMaxRows) fail(path, line, "more than " + std::to_string(kMaxRows) + " rows");
    std::vector<std::string> cells;
    std::stringstream ss(text);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(trimmed(cell));
    if (cells.size() != 6) fail(path, line, "expected 6 columns, got " + std::to_string(cells.size()));
    const int surface = parse_index(cells[0], path, line, kColumns[0]);
    const int point = parse_index(cells[1], path, line, kColumns[1]);
    if (surface == static_cast<int>(sections.surfaces.size()) + 1) {
      if (surface > kMaxStreamSurfaces) fail(path, line, "surface: at most " + std::to_string(kMaxStreamSurfaces) + " stream surfaces");
      sections.surfaces.emplace_back();
    }
    if (surface != static_cast<int>(sections.surfaces.size())) fail(path, line, "surface: surfaces must be numbered 1, 2, ... in order");
    auto& points = sections.surfaces.back();
    if (point != static_cast<int>(points.size()) + 1) fail(path, line, "point: points must be numbered 1, 2, ... in order on each surface");
    SectionPoint p;
    p.axial = parse_number(cells[2], path, line, kColumns[2]);
    p.radius = parse_number(cells[3], path, line, kColumns[3]);
    p.rtheta_suction = parse_number(cells[4], path, line, kColumns[4]);
    p.tangential_thickness = parse_number(cells[5], path, line, kColumns[5]);
    if (!(p.radius > 0)) fail(path, line, "radius_m: must be > 0");
    if (p.tangential_thickness < 0) fail(path, line, "tangential_thickness_m: must be >= 0");
    points.push_back(p);
  }
  if (!header_seen) fail(path, line, "header: missing");
  if (sections.blade_count < 1) fail(path, line, "blade_count: missing (a comment line '# blade_count = N')");
  try {
    sections.validate();
  } catch (const std::invalid_argument& e) {
    throw CaseError(path + ": " + e.what());
  }
  return sections;
}

}  // namespace hbtrack
