#include "hbtrack/results/results_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
  if (!out_) throw WriteFailed(path + ": write failed (disk full?)");
}

CsvAppender::CsvAppender(const std::string& path, size_t columns) : path_(path), out_(path, std::ios::app), columns_(columns) {
  if (!out_) throw std::runtime_error(path + ": cannot open for appending");
}

template <class Keep>
CsvAppender CsvAppender::keep_leading_rows(const std::string& path, const std::vector<std::string>& header, Keep keep, int expected) {
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
  while (std::getline(in, line) && keep(line, found)) {
    kept += line;
    kept += '\n';
    ++found;
  }
  if (found < expected)
    throw std::runtime_error(path + ": holds " + std::to_string(found) + " rows, the checkpoint " + std::to_string(expected));
  in.close();
  write_file_atomically(path, kept);
  return CsvAppender(path, header.size());
}

CsvAppender CsvAppender::continuing(const std::string& path, const std::vector<std::string>& header, int rows) {
  return keep_leading_rows(
      path, header, [rows](const std::string&, int found) { return found < rows; }, rows);
}

CsvAppender CsvAppender::continuing_points(const std::string& path, const std::vector<std::string>& header, int points) {
  // Rows are in point order: keep them up to the first of a point beyond the checkpoint.
  return keep_leading_rows(
      path, header, [points](const std::string& line, int) { return std::atof(line.c_str()) < points; }, 0);
}

void CsvAppender::append(const std::vector<double>& row) {
  if (row.size() != columns_) throw std::logic_error(path_ + ": row has the wrong number of columns");
  char buffer[32];
  std::string line;
  for (size_t i = 0; i < row.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%.17g", row[i]);
    if (i) line += ',';
    line += buffer;
  }
  line += '\n';
  // Every earlier row is flushed: the file's size is where this one starts. A row the disk took
  // only part of is cut off again, or the table could not be read back (export, --from).
  std::error_code ec;
  const auto before = std::filesystem::file_size(path_, ec);
  out_.write(line.data(), static_cast<std::streamsize>(line.size()));
  out_.flush();
  if (!out_) {
    if (!ec) {
      out_.close();
      [[maybe_unused]] const int ignored = ::truncate(path_.c_str(), static_cast<off_t>(before));
    }
    throw WriteFailed(path_ + ": write failed (disk full?)");
  }
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  // POSIX calls rather than a stream: a stream keeps the bytes in its buffer and reports a full
  // disk only when it is closed, where a destructor cannot say so (summary.json came out empty).
  const std::string tmp = path + ".tmp";
  const auto fail = [&](const std::string& what, int error) {
    ::unlink(tmp.c_str());
    throw WriteFailed(tmp + ": " + what + ": " + std::strerror(error) + (error == ENOSPC || error == EFBIG ? " (disk full?)" : ""));
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw WriteFailed(tmp + ": cannot open for writing: " + std::strerror(errno));
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      fail("write failed", error);
    }
    done += static_cast<std::size_t>(n);
  }
  // On the disk before the rename: after a crash the file is the old one or the whole new one.
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const int error = errno;
    ::close(fd);
    fail("fsync failed", error);
  }
  if (::close(fd) != 0) fail("close failed", errno);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail("cannot rename to " + path, errno);
}

void write_json_atomically(const std::string& path, const nlohmann::json& document) {
  write_file_atomically(path, document.dump(2) + '\n');
}

void ensure_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw std::runtime_error(dir + ": cannot create output directory");
}

}  // namespace hbtrack
