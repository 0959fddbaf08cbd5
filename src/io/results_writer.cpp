#include "hbtrack/io/results_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace hbtrack {

CsvAppender::CsvAppender(const std::string& path, const std::vector<std::string>& header)
    : path_(path), out_(path, std::ios::trunc), columns_(header.size()) {
  if (!out_) throw std::runtime_error(path + ": cannot open for writing");
  for (size_t i = 0; i < header.size(); ++i) out_ << (i ? "," : "") << header[i];
  out_ << '\n';
  out_.flush();
}

CsvAppender::CsvAppender(const std::string& path, size_t columns) : path_(path), out_(path, std::ios::app), columns_(columns) {
  if (!out_) throw std::runtime_error(path + ": cannot open for appending");
}

CsvAppender CsvAppender::continuing(const std::string& path, const std::vector<std::string>& header, int rows) {
  std::string expected_header;
  for (const std::string& h : header) {
    if (!expected_header.empty()) expected_header += ',';
    expected_header += h;
  }
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open (nothing to resume)");
  std::string kept, line;
  if (!std::getline(in, line) || line != expected_header) throw std::runtime_error(path + ":1: header differs from this case's columns");
  kept = line + '\n';
  int found = 0;
  while (found < rows && std::getline(in, line)) {
    kept += line;
    kept += '\n';
    ++found;
  }
  if (found < rows)
    throw std::runtime_error(path + ": holds " + std::to_string(found) + " rows, the checkpoint " + std::to_string(rows));
  in.close();
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << kept;
    if (!out) throw std::runtime_error(tmp + ": write failed (disk full?)");
  }
  std::filesystem::rename(tmp, path);
  return CsvAppender(path, header.size());
}

void CsvAppender::append(const std::vector<double>& row) {
  if (row.size() != columns_) throw std::logic_error(path_ + ": row has the wrong number of columns");
  char buffer[32];
  for (size_t i = 0; i < row.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%.17g", row[i]);
    out_ << (i ? "," : "") << buffer;
  }
  out_ << '\n';
  out_.flush();
  if (!out_) throw std::runtime_error(path_ + ": write failed (disk full?)");
}

void write_json_atomically(const std::string& path, const nlohmann::json& document) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    if (!out) throw std::runtime_error(tmp + ": cannot open for writing");
    out << document.dump(2) << '\n';
    if (!out) throw std::runtime_error(tmp + ": write failed (disk full?)");
  }
  std::filesystem::rename(tmp, path);
}

void ensure_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw std::runtime_error(dir + ": cannot create output directory");
}

}  // namespace hbtrack
