#include "hbtrack/io/matrix_readers.hpp"

#include "mat_header_check.hpp"

#include <matio.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace hbtrack {
namespace {

using Triplet = Eigen::Triplet<double>;

// Building an Eigen sparse matrix allocates (and zeroes) an index per row and per column, so a
// corrupt size field could demand gigabytes without a single entry behind it, and seconds of
// zeroing (fuzzing: a .mat header of 1e8 columns took over 30 s under the sanitizers). 5e6 is
// far above any model hbtrack solves and keeps dimensions well inside Eigen's int storage index.
constexpr std::int64_t kMaxDimension = 5'000'000;
static_assert(kMaxDimension < std::numeric_limits<int>::max());
// A corrupt or hostile header must not be able to request an absurd allocation.
constexpr std::int64_t kMaxEntries = 1'000'000'000;
// Reserve at most this up front; the vector grows only as real entries arrive.
constexpr std::size_t kMaxReserve = std::size_t{1} << 20;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

std::string errno_text(int error_number) { return std::generic_category().message(error_number); }

// Text from the file goes into error messages; keep those one short printable line.
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

// A missing file or a directory would otherwise surface as a confusing parse error.
void require_readable_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found)
    fail(path, "cannot open file: No such file or directory");
  if (ec) fail(path, "cannot open file: " + ec.message());
  if (std::filesystem::is_directory(status)) fail(path, "cannot open file: is a directory");
}

// ---------------------------------------------------------------------------------------------
// Matrix Market

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
        fail_line("size line must be 'rows columns entries' (3 integers), found " + std::to_string(size.count) +
                  " fields");
      rows = parse_size_field(size.token[0], "rows", kMaxDimension);
      cols = parse_size_field(size.token[1], "columns", kMaxDimension);
      declared_entries = parse_size_field(size.token[2], "entries", kMaxEntries);
    } else {
      if (size.count != 2)
        fail_line("size line must be 'rows columns' (2 integers) for array format, found " +
                  std::to_string(size.count) + " fields");
      rows = parse_size_field(size.token[0], "rows", kMaxDimension);
      cols = parse_size_field(size.token[1], "columns", kMaxDimension);
      // Both are at most kMaxDimension, so the product cannot overflow 64 bits.
      if (rows * cols > kMaxEntries)
        fail_line("array of " + std::to_string(rows) + " x " + std::to_string(cols) +
                  " entries exceeds the limit of " + std::to_string(kMaxEntries));
    }
    if (header.symmetry != MmSymmetry::general && rows != cols)
      fail_line("a symmetric or skew-symmetric matrix must be square, size line says " + std::to_string(rows) +
                " x " + std::to_string(cols));

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
  [[noreturn]] void fail_line(const std::string& what) const {
    fail(path_, "line " + std::to_string(line_number_) + ": " + what);
  }

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
      fail_line(std::string("size line: ") + what + " " + std::to_string(value) + " exceeds the limit of " +
                std::to_string(limit));
    return value;
  }

  // Returns the 0-based index.
  Eigen::Index parse_index(std::string_view token, std::int64_t extent, const char* what) const {
    std::int64_t index = 0;
    if (!parse_integer(token, index))
      fail_line(std::string(what) + " index " + single_quoted(token) + " is not an integer");
    if (index < 1 || index > extent)
      fail_line(std::string(what) + " index " + std::to_string(index) + " out of range 1.." + std::to_string(extent));
    return static_cast<Eigen::Index>(index - 1);
  }

  double parse_value(std::string_view token) const {
    if (header_.field == MmField::integer) {
      std::int64_t integer = 0;
      if (!parse_integer(token, integer))
        fail_line("value " + single_quoted(token) + " is not an integer (field is integer)");
      return static_cast<double>(integer);
    }
    double value = 0.0;
    switch (parse_real(token, value)) {
      case RealParse::malformed: fail_line("value " + single_quoted(token) + " is not a number");
      case RealParse::overflow: fail_line("value " + single_quoted(token) + " is out of range for a double");
      case RealParse::ok: break;
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
        fail(path_, "file ends after " + std::to_string(k) + " of " + std::to_string(declared_entries) +
                        " entries declared on the size line");
      const Fields entry = split_fields(line);
      if (entry.count != expected_fields)
        fail_line("expected " + std::to_string(expected_fields) + " numbers (" +
                  (has_value ? "row column value" : "row column") + "), found " + std::to_string(entry.count));
      const Eigen::Index row = parse_index(entry.token[0], rows_, "row");
      const Eigen::Index col = parse_index(entry.token[1], cols_, "column");
      const double value = has_value ? parse_value(entry.token[2]) : 1.0;
      if (header_.symmetry != MmSymmetry::general) {
        // Mirroring entries from both triangles would silently double them.
        seen_lower = seen_lower || row > col;
        seen_upper = seen_upper || row < col;
        if (seen_lower && seen_upper)
          fail_line("symmetric file stores entries in both triangles; store only the lower (or upper) one");
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
        case MmSymmetry::general: return 0;
        case MmSymmetry::symmetric: return col;
        case MmSymmetry::skew_symmetric: return col + 1;
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
          fail(path_, "file ends after " + std::to_string(read) + " of " + std::to_string(expected) +
                          " array entries");
        const Fields entry = split_fields(line);
        if (entry.count != 1)
          fail_line("expected 1 number per line in array format, found " + std::to_string(entry.count));
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

// ---------------------------------------------------------------------------------------------
// MATLAB .mat via libmatio

struct MatFileCloser {
  void operator()(mat_t* file) const { Mat_Close(file); }
};
struct MatVarFreer {
  void operator()(matvar_t* variable) const { Mat_VarFree(variable); }
};
using MatFile = std::unique_ptr<mat_t, MatFileCloser>;
using MatVar = std::unique_ptr<matvar_t, MatVarFreer>;

const char* class_name(matio_classes class_type) {
  switch (class_type) {
    case MAT_C_EMPTY: return "empty";
    case MAT_C_CELL: return "cell";
    case MAT_C_STRUCT: return "struct";
    case MAT_C_OBJECT: return "object";
    case MAT_C_CHAR: return "char";
    case MAT_C_SPARSE: return "sparse";
    case MAT_C_DOUBLE: return "double";
    case MAT_C_SINGLE: return "single";
    case MAT_C_INT8: return "int8";
    case MAT_C_UINT8: return "uint8";
    case MAT_C_INT16: return "int16";
    case MAT_C_UINT16: return "uint16";
    case MAT_C_INT32: return "int32";
    case MAT_C_UINT32: return "uint32";
    case MAT_C_INT64: return "int64";
    case MAT_C_UINT64: return "uint64";
    case MAT_C_FUNCTION: return "function handle";
    case MAT_C_OPAQUE: return "opaque object";
  }
  return "unknown class";
}

template <class T>
double load_as_double(const void* data, std::size_t index) {
  // memcpy because matio gives no alignment promise for every storage type.
  T element;
  std::memcpy(&element, static_cast<const unsigned char*>(data) + index * sizeof(T), sizeof(T));
  return static_cast<double>(element);
}

struct ElementLoader {
  double (*load)(const void*, std::size_t) = nullptr;
  std::size_t width = 0;
};

// matio stores each class at its own width (e.g. int16 stays int16), so pick the reader per type.
ElementLoader loader_for(matio_types data_type) {
  switch (data_type) {
    case MAT_T_DOUBLE: return {&load_as_double<double>, sizeof(double)};
    case MAT_T_SINGLE: return {&load_as_double<float>, sizeof(float)};
    case MAT_T_INT8: return {&load_as_double<std::int8_t>, sizeof(std::int8_t)};
    case MAT_T_UINT8: return {&load_as_double<std::uint8_t>, sizeof(std::uint8_t)};
    case MAT_T_INT16: return {&load_as_double<std::int16_t>, sizeof(std::int16_t)};
    case MAT_T_UINT16: return {&load_as_double<std::uint16_t>, sizeof(std::uint16_t)};
    case MAT_T_INT32: return {&load_as_double<std::int32_t>, sizeof(std::int32_t)};
    case MAT_T_UINT32: return {&load_as_double<std::uint32_t>, sizeof(std::uint32_t)};
    case MAT_T_INT64: return {&load_as_double<std::int64_t>, sizeof(std::int64_t)};
    case MAT_T_UINT64: return {&load_as_double<std::uint64_t>, sizeof(std::uint64_t)};
    default: return {};
  }
}

class MatVariableReader {
 public:
  MatVariableReader(const std::string& path, const std::string& name) : path_(path), name_(name) {}

  Eigen::SparseMatrix<double> read() {
    require_readable_file(path_);
    if (name_.empty()) fail(path_, "variable name is empty");
    check_mat_headers(path_);
    const MatFile file{Mat_Open(path_.c_str(), MAT_ACC_RDONLY)};
    if (!file) fail(path_, "not a readable MAT file (v4, v5, v7 or v7.3)");

    // Vet the header before Mat_VarRead allocates whatever it claims: a corrupt size field
    // would otherwise make libmatio attempt a multi-gigabyte allocation.
    {
      const MatVar info{Mat_VarReadInfo(file.get(), name_.c_str())};
      if (!info) fail_variable("not found; available: " + list_variables(file.get()));
      check_header(*info);
      check_plausible_size(*info, Mat_GetVersion(file.get()));
    }
    const MatVar variable{Mat_VarRead(file.get(), name_.c_str())};
    if (!variable) fail_variable("could not be read (corrupt or truncated file?)");
    const auto [rows, cols] = check_header(*variable);

    Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    const std::vector<Triplet> triplets =
        variable->class_type == MAT_C_SPARSE ? sparse_triplets(*variable, rows, cols)
                                             : dense_triplets(*variable, rows, cols);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    return matrix;
  }

 private:
  [[noreturn]] void fail_variable(const std::string& what) const {
    fail(path_, "variable " + single_quoted(name_) + ": " + what);
  }

  // Returns {rows, cols} once the variable is known to be a real 2-D numeric or sparse matrix.
  std::pair<std::size_t, std::size_t> check_header(const matvar_t& variable) const {
    const bool numeric = variable.class_type >= MAT_C_DOUBLE && variable.class_type <= MAT_C_UINT64;
    if (!numeric && variable.class_type != MAT_C_SPARSE)
      fail_variable("is a " + std::string(class_name(variable.class_type)) + " array; expected a numeric matrix");
    if (variable.isComplex) fail_variable("is complex; only real matrices are supported");
    if (variable.rank != 2 || variable.dims == nullptr)
      fail_variable("has " + std::to_string(variable.rank) + " dimensions; expected a 2-D matrix");
    const std::size_t rows = variable.dims[0];
    const std::size_t cols = variable.dims[1];
    if (rows > static_cast<std::size_t>(kMaxDimension) || cols > static_cast<std::size_t>(kMaxDimension))
      fail_variable("size " + std::to_string(rows) + " x " + std::to_string(cols) + " exceeds the limit of " +
                    std::to_string(kMaxDimension) + " per dimension");
    return {rows, cols};
  }

  void check_plausible_size(const matvar_t& info, mat_ft version) const {
    if (info.class_type == MAT_C_SPARSE) return;  // its size depends on nnz, which the header lacks
    const std::size_t elements = info.dims[0] * info.dims[1];  // both at most kMaxDimension
    if (elements > static_cast<std::size_t>(kMaxEntries))
      fail_variable("has " + std::to_string(elements) + " elements, more than the limit of " +
                    std::to_string(kMaxEntries));
    // v4/v5 store every element in at least one byte, and zlib expands at most ~1032:1.
    // v7.3 (HDF5) may legitimately store unwritten data as a fill value, so it is not bounded.
    if (version == MAT_FT_MAT73) return;
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path_, ec);
    if (ec) return;
    constexpr std::uintmax_t kMaxZlibRatio = 1032;
    const std::uintmax_t max_elements =
        info.compression == MAT_COMPRESSION_ZLIB ? file_bytes * kMaxZlibRatio : file_bytes;
    if (elements > max_elements)
      fail_variable("header claims " + std::to_string(info.dims[0]) + " x " + std::to_string(info.dims[1]) +
                    " elements but the file has only " + std::to_string(file_bytes) + " bytes (corrupt file?)");
  }

  static std::string list_variables(mat_t* file) {
    // Bounded so a corrupt directory cannot make the message (or the loop) unbounded.
    constexpr std::size_t kMaxListed = 20;
    constexpr std::size_t kMaxScanned = 100000;
    if (Mat_Rewind(file) != 0) return "(could not list variables)";
    std::string names;
    std::size_t found = 0;
    for (std::size_t scanned = 0; scanned < kMaxScanned; ++scanned) {
      const MatVar info{Mat_VarReadNextInfo(file)};
      if (!info) break;
      if (info->name == nullptr) continue;
      if (found < kMaxListed) names += (found == 0 ? "" : ", ") + printable(info->name);
      ++found;
    }
    if (found == 0) return "(none)";
    if (found > kMaxListed) names += ", ... (" + std::to_string(found) + " in total)";
    return names;
  }

  std::vector<Triplet> dense_triplets(const matvar_t& variable, std::size_t rows, std::size_t cols) const {
    const ElementLoader loader = loader_for(variable.data_type);
    if (loader.load == nullptr) fail_variable("has an unsupported element type");
    const std::size_t count = rows * cols;  // both at most kMaxDimension
    if (count == 0) return {};
    if (variable.data == nullptr || variable.nbytes / loader.width < count)
      fail_variable("holds fewer elements than its size " + std::to_string(rows) + " x " + std::to_string(cols));

    std::vector<Triplet> triplets;
    triplets.reserve(count < kMaxReserve ? count : kMaxReserve);
    for (std::size_t k = 0; k < count; ++k) {
      const double value = loader.load(variable.data, k);
      const std::size_t row = k % rows;  // MATLAB stores column-major
      const std::size_t col = k / rows;
      if (!std::isfinite(value)) fail_variable("non-finite value at " + position(row, col));
      if (value != 0.0) triplets.emplace_back(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(col), value);
    }
    return triplets;
  }

  std::vector<Triplet> sparse_triplets(const matvar_t& variable, std::size_t rows, std::size_t cols) const {
    const auto* sparse = static_cast<const mat_sparse_t*>(variable.data);
    if (sparse == nullptr) fail_variable("sparse data is missing");
    const ElementLoader loader = loader_for(variable.data_type);
    if (loader.load == nullptr) fail_variable("sparse matrix has an unsupported element type");
    // Check the CSC arrays against each other before trusting any index from the file.
    if (sparse->jc == nullptr || sparse->njc != cols + 1)
      fail_variable("corrupt sparse column pointers (expected " + std::to_string(cols + 1) + ", found " +
                    std::to_string(sparse->njc) + ")");
    const std::size_t nonzeros = sparse->jc[cols];
    if (sparse->jc[0] != 0 || nonzeros > sparse->nir || nonzeros > sparse->ndata ||
        (nonzeros > 0 && (sparse->ir == nullptr || sparse->data == nullptr)))
      fail_variable("corrupt sparse data (column pointers disagree with the stored entries)");

    std::vector<Triplet> triplets;
    triplets.reserve(nonzeros < kMaxReserve ? nonzeros : kMaxReserve);
    for (std::size_t col = 0; col < cols; ++col) {
      const std::size_t begin = sparse->jc[col];
      const std::size_t end = sparse->jc[col + 1];
      if (end < begin || end > nonzeros) fail_variable("corrupt sparse column pointers (not ascending)");
      for (std::size_t k = begin; k < end; ++k) {
        const std::size_t row = sparse->ir[k];
        if (row >= rows)
          fail_variable("corrupt sparse row index " + std::to_string(row) + " in column " + std::to_string(col + 1));
        const double value = loader.load(sparse->data, k);
        if (!std::isfinite(value)) fail_variable("non-finite value at " + position(row, col));
        triplets.emplace_back(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(col), value);
      }
    }
    return triplets;
  }

  // 1-based, as the user would index it in MATLAB.
  static std::string position(std::size_t row, std::size_t col) {
    std::string text(1, '(');
    text += std::to_string(row + 1);
    text += ", ";
    text += std::to_string(col + 1);
    text += ')';
    return text;
  }

  const std::string& path_;
  const std::string& name_;
};

// A handful of entries can describe a matrix far too big to hold densely; refuse rather than
// let the dense copy exhaust memory. `where` is the message prefix (path, plus variable for .mat).
Eigen::MatrixXd to_dense(const std::string& where, const Eigen::SparseMatrix<double>& sparse) {
  const std::int64_t entries = static_cast<std::int64_t>(sparse.rows()) * static_cast<std::int64_t>(sparse.cols());
  if (entries > kMaxEntries)
    fail(where, std::to_string(sparse.rows()) + " x " + std::to_string(sparse.cols()) +
                    " is too large to read as a dense matrix (limit " + std::to_string(kMaxEntries) +
                    " entries); use the sparse reader");
  return Eigen::MatrixXd(sparse);
}

}  // namespace

Eigen::SparseMatrix<double> read_matrix_market_sparse(const std::string& path) {
  require_readable_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file: " + errno_text(errno));
  return MatrixMarketParser(path, in).parse();
}

Eigen::MatrixXd read_matrix_market(const std::string& path) {
  return to_dense(path, read_matrix_market_sparse(path));
}

void write_matrix_market(const std::string& path, const Eigen::SparseMatrix<double>& matrix) {
  // Refuse before touching the file: the reader would reject a non-finite value anyway.
  Eigen::Index entries = 0;
  for (Eigen::Index outer = 0; outer < matrix.outerSize(); ++outer)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, outer); it; ++it) {
      if (!std::isfinite(it.value()))
        fail(path, "cannot write non-finite value at (" + std::to_string(it.row() + 1) + ", " +
                       std::to_string(it.col() + 1) + ")");
      ++entries;
    }

  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::unique_ptr<std::FILE, FileCloser> file{std::fopen(path.c_str(), "w")};
  if (!file) fail(path, "cannot open for writing: " + errno_text(errno));

  std::fprintf(file.get(), "%%%%MatrixMarket matrix coordinate real general\n");
  std::fprintf(file.get(), "%lld %lld %lld\n", static_cast<long long>(matrix.rows()),
               static_cast<long long>(matrix.cols()), static_cast<long long>(entries));
  for (Eigen::Index outer = 0; outer < matrix.outerSize(); ++outer)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, outer); it; ++it)
      std::fprintf(file.get(), "%lld %lld %.17g\n", static_cast<long long>(it.row() + 1),
                   static_cast<long long>(it.col() + 1), it.value());

  const bool write_failed = std::ferror(file.get()) != 0;
  // fclose flushes, so its result is the last chance to notice a full disk.
  const bool close_failed = std::fclose(file.release()) != 0;
  if (write_failed || close_failed) fail(path, "write failed: " + errno_text(errno));
}

Eigen::SparseMatrix<double> read_mat_variable_sparse(const std::string& path, const std::string& name) {
  return MatVariableReader(path, name).read();
}

Eigen::MatrixXd read_mat_variable(const std::string& path, const std::string& name) {
  return to_dense(path + ": variable " + single_quoted(name), read_mat_variable_sparse(path, name));
}

}  // namespace hbtrack
