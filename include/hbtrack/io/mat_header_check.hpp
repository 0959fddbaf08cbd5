#pragma once
// Walks a MAT file's element headers before libmatio reads it (libmatio sizes its allocations
// from those headers without checking them against the file).
#include <string>

namespace hbtrack {

// Throws std::runtime_error("PATH: corrupt MAT file: ...") when a header claims more bytes than
// the file (or its enclosing element) holds, or a sub-element has an unknown type or a size that
// is not a whole number of its elements. Files it cannot classify are left to libmatio.
void check_mat_headers(const std::string& path);

}  // namespace hbtrack
