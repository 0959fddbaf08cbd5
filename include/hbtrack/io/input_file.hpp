#pragma once
// Bounded reading of input files. Only regular files are read: a device (/dev/zero), a pipe or a
// directory could be read until memory runs out. TOML text is checked for nesting depth before
// it is parsed, because the TOML parser recurses once per bracket and a few kilobytes of `[`
// overflow its stack.
#include <cstddef>
#include <string>
#include <string_view>

namespace hbtrack {

// A case file (or a text given on the command line) larger than this is refused: big matrices
// belong in .mtx or .mat files, which are sized against the file before they are read.
inline constexpr std::size_t kMaxCaseFileBytes = std::size_t{64} << 20;

// Arrays and inline tables nested deeper than this are refused (a case file nests two or three).
inline constexpr int kMaxTomlNesting = 64;

// Throws CaseError "PATH: does not exist" / "PATH: is not a regular file (...)" naming `what`.
void require_regular_file(const std::string& path, const std::string& what);

// The whole of a regular file of at most max_bytes; CaseError when it is not one or is larger.
std::string read_bounded_file(const std::string& path, std::size_t max_bytes, const std::string& what);

// Throws CaseError "SOURCE:LINE: ..." when `text` nests arrays or inline tables deeper than
// kMaxTomlNesting; brackets inside strings and comments do not count.
void check_toml_nesting(std::string_view text, const std::string& source);

}  // namespace hbtrack
