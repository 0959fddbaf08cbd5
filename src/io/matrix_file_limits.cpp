#include "matrix_file_limits.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace hbtrack::matrix_file {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + ": " + what); }

std::string errno_text(int error_number) { return std::generic_category().message(error_number); }

std::string printable(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  std::string shown;
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    shown += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (text.size() > kMaxShown) shown += "...";
  return shown;
}

// Appending instead of "'" + ... sidesteps a GCC 12 -Wrestrict false positive (PR 105329).
std::string single_quoted(std::string_view text) {
  std::string quoted(1, '\'');
  quoted += printable(text);
  quoted += '\'';
  return quoted;
}

void require_readable_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found) fail(path, "cannot open file: No such file or directory");
  if (ec) fail(path, "cannot open file: " + ec.message());
  if (std::filesystem::is_directory(status)) fail(path, "cannot open file: is a directory");
}

Eigen::MatrixXd to_dense(const std::string& where, const Eigen::SparseMatrix<double>& sparse) {
  const std::int64_t entries = static_cast<std::int64_t>(sparse.rows()) * static_cast<std::int64_t>(sparse.cols());
  if (entries > kMaxDenseEntries)
    fail(where, std::to_string(sparse.rows()) + " x " + std::to_string(sparse.cols()) + " is too large to read as a dense matrix (limit " +
                    std::to_string(kMaxDenseEntries) + " entries, 128 MB); use the sparse reader");
  return Eigen::MatrixXd(sparse);
}

}  // namespace hbtrack::matrix_file
