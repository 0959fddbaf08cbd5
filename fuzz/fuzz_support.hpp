#pragma once
// What the fuzz targets share. The readers under fuzz take a path (toml11 and libmatio open the
// file themselves), so each input is written to a per-process temporary file first; a reader
// may refuse it only with std::runtime_error and a one-line message (the CLI's contract).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace hbtrack::fuzz {

inline std::string write_input(const uint8_t* data, size_t size, const char* suffix) {
  std::string path = "/tmp/hbtrack_fuzz_";
  path += std::to_string(getpid());
  path += suffix;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// Runs read(): returning or a one-line std::runtime_error pass; a multi-line message aborts (a
// finding), as does any other exception (uncaught) or a sanitizer report.
template <class Read>
void read_or_refuse_in_one_line(Read read) {
  try {
    read();
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).find('\n') != std::string::npos) std::abort();
  }
}

}  // namespace hbtrack::fuzz
