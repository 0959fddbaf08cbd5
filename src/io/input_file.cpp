#include "hbtrack/io/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "hbtrack/io/case_file.hpp"
#include "toml_scan.hpp"

namespace hbtrack {

namespace fs = std::filesystem;

void require_regular_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw CaseError(path + ": file does not exist");
  if (fs::is_directory(status)) throw CaseError(path + ": is a directory, expected " + what);
  if (!fs::is_regular_file(status)) throw CaseError(path + ": is not a regular file (a device, pipe or socket), expected " + what);
}

std::string read_bounded_file(const std::string& path, std::size_t max_bytes, const std::string& what) {
  require_regular_file(path, what);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw CaseError(path + ": cannot read: " + std::strerror(errno));
  // In chunks, stopping one byte past the limit: the file may grow after the check.
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= max_bytes && file.read(chunk, sizeof chunk).gcount() > 0)
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
  if (file.bad()) throw CaseError(path + ": cannot read: " + std::strerror(errno));
  if (text.size() > max_bytes)
    throw CaseError(path + ": larger than " +
                    (max_bytes >= (1u << 20) ? std::to_string(max_bytes >> 20) + " MiB" : std::to_string(max_bytes) + " bytes") +
                    ", the limit for " + what);
  return text;
}

void check_toml_nesting(std::string_view text, const std::string& source) {
  int depth = 0;
  scan_toml_code(text, [&](std::size_t, char ch, long line) {
    if (ch == '[' || ch == '{') {
      if (++depth > kMaxTomlNesting)
        throw CaseError(source + ":" + std::to_string(line) + ": arrays or inline tables nested deeper than " +
                        std::to_string(kMaxTomlNesting) + " levels");
    } else if ((ch == ']' || ch == '}') && depth > 0) {
      --depth;
    }
  });
}

}  // namespace hbtrack
