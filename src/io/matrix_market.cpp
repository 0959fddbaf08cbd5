#include "hbtrack/io/matrix_market.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "matrix_file_limits.hpp"

namespace hbtrack {

using namespace matrix_file;

namespace {

enum class MmFormat { coordinate, array };
enum class MmField { real, integer, pattern };
enum class MmSymmetry { general, symmetric, skew_symmetric };

struct MmHeader {
  MmFormat format = MmFormat::coordinate;
  MmField field = MmField::real;
  MmSymmetry symmetry = MmSymmetry::general;
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

// The first few whitespace-separated fields of a line plus how many there were in total, so
// "too many numbers" is reported without storing an unbounded list.
struct Fields {
  static constexpr std::size_t kStored = 5;
  std::array<std::string_view, kStored> token{};
  std::size_t count = 0;
};

Fields split_fields(std::string_view line) {
  Fields fields;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && is_blank(line[pos])) ++pos;
    if (pos == line.size()) break;
    const std::size_t start = pos;
    while (pos < line.size() && !is_blank(line[pos])) ++pos;
    if (fields.count < Fields::kStored) fields.token[fields.count] = line.substr(start, pos - start);
    ++fields.count;
  }
  return fields;
}

// from_chars rejects a leading '+', which some writers emit.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-') token.remove_prefix(1);
  return token;
}

bool parse_integer(std::string_view token, std::int64_t& value) {
  token = without_plus(token);
  const char* end = token.data() + token.size();
  const auto [stop, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && stop == end;
}

enum class RealParse { ok, malformed, overflow };

RealParse parse_real(std::string_view token, double& value) {
  token = without_plus(token);
  const char* end = token.data() + token.size();
  const auto [stop, ec] = std::from_chars(token.data(), end, value);
  if (ec == std::errc::invalid_argument || stop != end) return RealParse::malformed;
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports underflow the same way as overflow; a negative exponent means the
    // value is merely too small to represent, which rounds to zero harmlessly.
    const std::size_t exponent = token.find_last_of("eE");
    if (exponent != std::string_view::npos && exponent + 1 < token.size() && token[exponent + 1] == '-') {
      value = 0.0;
      return RealParse::ok;
    }
    return RealParse::overflow;
  }
  return RealParse::ok;
}

class MatrixMarketParser {
 public:
  MatrixMarketParser(const std::string& path, std::istream& in) : path_(path), in_(in) {}

  Eigen::SparseMatrix<double> parse() {
    const MmHeader header = parse_banner();
    std::string_view line;
    if (!next_data_line(line)) fail(path_, "missing size line after the banner");
    const Fields size = split_fields(line);
    std::int64_t rows = 0;
    std::int64_t cols = 0;
    std::int64_t declared_entries = 0;
    if (header.format == MmFormat::coordinate) {
      if (size.count != 3)
        fail_line("size line must be 'rows columns entries' (3 integers), found " + std::to_string(size.count) + " fields");
      rows = parse_size_field(size.token[0], "rows", kMaxDimension);
      cols = parse_size_field(size.token[1], "columns", kMaxDimension);
      declared_entries = parse_size_field(size.token[2], "entries", kMaxEntries);
    } else {
      if (size.count != 2)
        fail_line("size line must be 'rows columns' (2 integers) for array format, found " + std::to_string(size.count) + " fields");
      rows = parse_size_field(size.token[0], "rows", kMaxDimension);
      cols = parse_size_field(size.token[1], "columns", kMaxDimension);
      // Both are at most kMaxDimension, so the product cannot overflow 64 bits.
      if (rows * cols > kMaxEntries)
        fail_line("array of " + std::to_string(rows) + " x " + std::to_string(cols) + " entries exceeds the limit of " +
                  std::to_string(kMaxEntries));
    }
    if (header.symmetry != MmSymmetry::general && rows != cols)
      fail_line("a symmetric or skew-symmetric matrix must be square, size line says " + std::to_string(rows) + " x " +
                std::to_string(cols));

    rows_ = rows;
    cols_ = cols;
    header_ = header;
    if (header.format == MmFormat::coordinate)
      read_coordinate_entries(declared_entries);
    else
      read_array_entries();
    reject_trailing_entries();

    Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    matrix.setFromTriplets(triplets_.begin(), triplets_.end());  // sums duplicates
    return matrix;
  }

 private:
  [[noreturn]] void fail_line(const std::string& what) const { fail(path_, "line " + std::to_string(line_number_) + ": " + what); }

  bool next_line(std::string_view& line) {
    if (!std::getline(in_, buffer_)) {
      if (in_.bad()) fail(path_, "read error after line " + std::to_string(line_number_));
      return false;
    }
    ++line_number_;
    line = buffer_;
    return true;
  }

  // Skips % comments and blank lines, which may appear anywhere after the banner.
  bool next_data_line(std::string_view& line) {
    while (next_line(line)) {
      std::size_t first = 0;
      while (first < line.size() && is_blank(line[first])) ++first;
      if (first == line.size() || line[first] == '%') continue;
      return true;
    }
    return false;
  }

  MmHeader parse_banner() {
    std::string_view line;
    constexpr std::string_view kBanner = "%%MatrixMarket";
    if (!next_line(line) || !equals_ignoring_case(line.substr(0, kBanner.size()), kBanner))
      fail(path_, "line 1: missing '%%MatrixMarket' banner (is this a Matrix Market file?)");
    const Fields banner = split_fields(line);
    if (banner.count != 5 || !equals_ignoring_case(banner.token[0], kBanner))
      fail_line("banner must be '%%MatrixMarket matrix <format> <field> <symmetry>'");
    if (!equals_ignoring_case(banner.token[1], "matrix"))
      fail_line("unsupported object " + single_quoted(banner.token[1]) + " (only 'matrix' is supported)");

    MmHeader header;
    const std::string_view format = banner.token[2];
    if (equals_ignoring_case(format, "coordinate"))
      header.format = MmFormat::coordinate;
    else if (equals_ignoring_case(format, "array"))
      header.format = MmFormat::array;
    else
      fail_line("unknown format " + single_quoted(format) + " (expected coordinate or array)");

    const std::string_view field = banner.token[3];
    if (equals_ignoring_case(field, "real"))
      header.field = MmField::real;
    else if (equals_ignoring_case(field, "integer"))
      header.field = MmField::integer;
    else if (equals_ignoring_case(field, "pattern"))
      header.field = MmField::pattern;
    else if (equals_ignoring_case(field, "complex"))
      fail_line("complex matrices are not supported (field must be real, integer or pattern)");
    else
      fail_line("unknown field " + single_quoted(field) + " (expected real, integer or pattern)");

    const std::string_view symmetry = banner.token[4];
    if (equals_ignoring_case(symmetry, "general"))
      header.symmetry = MmSymmetry::general;
    else if (equals_ignoring_case(symmetry, "symmetric"))
      header.symmetry = MmSymmetry::symmetric;
    else if (equals_ignoring_case(symmetry, "skew-symmetric"))
      header.symmetry = MmSymmetry::skew_symmetric;
    else if (equals_ignoring_case(symmetry, "hermitian"))
      fail_line("hermitian matrices are not supported (symmetry must be general, symmetric or skew-symmetric)");
    else
      fail_line("unknown symmetry " + single_quoted(symmetry) + " (expected general, symmetric or skew-symmetric)");

    // The standard defines neither combination: array has no positions to omit, and a
    // skew-symmetric pattern has no sign to mirror.
    if (header.field == MmField::pattern && header.format == MmFormat::array)
      fail_line("pattern field is only valid with coordinate format");
    if (header.field == MmField::pattern && header.symmetry == MmSymmetry::skew_symmetric)
      fail_line("pattern field cannot be skew-symmetric");
    return header;
  }

  std::int64_t parse_size_field(std::string_view token, const char* what, std::int64_t limit) const {
    std::int64_t value = 0;
    if (!parse_integer(token, value) || value < 0)
      fail_line(std::string("size line: ") + what + " " + single_quoted(token) + " is not a non-negative integer");
    if (value > limit)
      fail_line(std::string("size line: ") + what + " " + std::to_string(value) + " exceeds the limit of " + std::to_string(limit));
    return value;
  }

  // Returns the 0-based index.
  Eigen::Index parse_index(std::string_view token, std::int64_t extent, const char* what) const {
    std::int64_t index = 0;
    if (!parse_integer(token, index)) fail_line(std::string(what) + " index " + single_quoted(token) + " is not an integer");
    if (index < 1 || index > extent)
      fail_line(std::string(what) + " index " + std::to_string(index) + " out of range 1.." + std::to_string(extent));
    return static_cast<Eigen::Index>(index - 1);
  }

  double parse_value(std::string_view token) const {
    if (header_.field == MmField::integer) {
      std::int64_t integer = 0;
      if (!parse_integer(token, integer)) fail_line("value " + single_quoted(token) + " is not an integer (field is integer)");
      return static_cast<double>(integer);
    }
    double value = 0.0;
    switch (parse_real(token, value)) {
      case RealParse::malformed:
        fail_line("value " + single_quoted(token) + " is not a number");
      case RealParse::overflow:
        fail_line("value " + single_quoted(token) + " is out of range for a double");
      case RealParse::ok:
        break;
    }
    if (!std::isfinite(value)) fail_line("value " + single_quoted(token) + " is not finite");
    return value;
  }

  void reserve(std::int64_t stored_entries) {
    const std::int64_t mirrored = header_.symmetry == MmSymmetry::general ? 1 : 2;
    const auto wanted = static_cast<std::size_t>(stored_entries * mirrored);
    triplets_.reserve(wanted < kMaxReserve ? wanted : kMaxReserve);
  }

  // Adds one stored entry and, for the symmetric kinds, its mirror image.
  void add_entry(Eigen::Index row, Eigen::Index col, double value) {
    triplets_.emplace_back(row, col, value);
    if (row == col || header_.symmetry == MmSymmetry::general) return;
    const double mirrored = header_.symmetry == MmSymmetry::skew_symmetric ? -value : value;
    triplets_.emplace_back(col, row, mirrored);
  }

  void read_coordinate_entries(std::int64_t declared_entries) {
    reserve(declared_entries);
    const bool has_value = header_.field != MmField::pattern;
    const std::size_t expected_fields = has_value ? 3 : 2;
    bool seen_lower = false;
    bool seen_upper = false;
    std::string_view line;
    for (std::int64_t k = 0; k < declared_entries; ++k) {
      if (!next_data_line(line))
        fail(path_,
             "file ends after " + std::to_string(k) + " of " + std::to_string(declared_entries) + " entries declared on the size line");
      const Fields entry = split_fields(line);
      if (entry.count != expected_fields)
        fail_line("expected " + std::to_string(expected_fields) + " numbers (" + (has_value ? "row column value" : "row column") +
                  "), found " + std::to_string(entry.count));
      const Eigen::Index row = parse_index(entry.token[0], rows_, "row");
      const Eigen::Index col = parse_index(entry.token[1], cols_, "column");
      const double value = has_value ? parse_value(entry.token[2]) : 1.0;
      if (header_.symmetry != MmSymmetry::general) {
        // Mirroring entries from both triangles would silently double them.
        seen_lower = seen_lower || row > col;
        seen_upper = seen_upper || row < col;
        if (seen_lower && seen_upper) fail_line("symmetric file stores entries in both triangles; store only the lower (or upper) one");
        if (row == col && header_.symmetry == MmSymmetry::skew_symmetric && value != 0.0)
          fail_line("skew-symmetric matrix has a nonzero diagonal entry");
      }
      add_entry(row, col, value);
    }
  }

  // Column-major, and only the lower triangle (strictly lower when skew) for the symmetric kinds.
  void read_array_entries() {
    const auto first_stored_row = [this](std::int64_t col) -> std::int64_t {
      switch (header_.symmetry) {
        case MmSymmetry::general:
          return 0;
        case MmSymmetry::symmetric:
          return col;
        case MmSymmetry::skew_symmetric:
          return col + 1;
      }
      return 0;
    };
    std::int64_t expected = 0;
    for (std::int64_t col = 0; col < cols_; ++col) expected += std::max<std::int64_t>(rows_ - first_stored_row(col), 0);
    reserve(expected);

    std::int64_t read = 0;
    std::string_view line;
    for (std::int64_t col = 0; col < cols_; ++col) {
      for (std::int64_t row = first_stored_row(col); row < rows_; ++row) {
        if (!next_data_line(line))
          fail(path_, "file ends after " + std::to_string(read) + " of " + std::to_string(expected) + " array entries");
        const Fields entry = split_fields(line);
        if (entry.count != 1) fail_line("expected 1 number per line in array format, found " + std::to_string(entry.count));
        const double value = parse_value(entry.token[0]);
        ++read;
        if (value != 0.0) add_entry(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(col), value);
      }
    }
  }

  void reject_trailing_entries() {
    std::string_view line;
    if (next_data_line(line)) fail_line("more entries than the size line declares");
  }

  const std::string& path_;
  std::istream& in_;
  std::string buffer_;
  std::int64_t line_number_ = 0;
  MmHeader header_;
  std::int64_t rows_ = 0;
  std::int64_t cols_ = 0;
  std::vector<Triplet> triplets_;
};

}  // namespace

Eigen::SparseMatrix<double> read_matrix_market_sparse(const std::string& path) {
  require_readable_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file: " + errno_text(errno));
  return MatrixMarketParser(path, in).parse();
}

Eigen::MatrixXd read_matrix_market(const std::string& path) { return to_dense(path, read_matrix_market_sparse(path)); }

void write_matrix_market(const std::string& path, const Eigen::SparseMatrix<double>& matrix) {
  // Refuse before touching the file: the reader would reject a non-finite value anyway.
  Eigen::Index entries = 0;
  for (Eigen::Index outer = 0; outer < matrix.outerSize(); ++outer)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, outer); it; ++it) {
      if (!std::isfinite(it.value()))
        fail(path, "cannot write non-finite value at (" + std::to_string(it.row() + 1) + ", " + std::to_string(it.col() + 1) + ")");
      ++entries;
    }

  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::unique_ptr<std::FILE, FileCloser> file{std::fopen(path.c_str(), "w")};
  if (!file) fail(path, "cannot open for writing: " + errno_text(errno));

  std::fprintf(file.get(), "%%%%MatrixMarket matrix coordinate real general\n");
  std::fprintf(file.get(), "%lld %lld %lld\n", static_cast<long long>(matrix.rows()), static_cast<long long>(matrix.cols()),
               static_cast<long long>(entries));
  for (Eigen::Index outer = 0; outer < matrix.outerSize(); ++outer)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, outer); it; ++it)
      std::fprintf(file.get(), "%lld %lld %.17g\n", static_cast<long long>(it.row() + 1), static_cast<long long>(it.col() + 1), it.value());

  const bool write_failed = std::ferror(file.get()) != 0;
  // fclose flushes, so its result is the last chance to notice a full disk.
  const bool close_failed = std::fclose(file.release()) != 0;
  if (write_failed || close_failed) fail(path, "write failed: " + errno_text(errno));
}

}  // namespace hbtrack
