#include "hbtrack/io/mat_header_check.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "matrix_file_limits.hpp"

namespace hbtrack {
namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + ": " + what); }

// The byte width of a v5 data type (miINT8 = 1 ... miUTF32 = 18); 0 for the reserved and
// unknown types, which no writer produces. miMATRIX and miCOMPRESSED hold other elements: 1.
unsigned v5_type_width(std::uint32_t type) {
  switch (type) {
    case 1:
    case 2:
    case 16:
    case 14:
    case 15:
      return 1;  // int8, uint8, utf8; matrix, compressed
    case 3:
    case 4:
    case 17:
      return 2;  // int16, uint16, utf16
    case 5:
    case 6:
    case 7:
    case 18:
      return 4;  // int32, uint32, single, utf32
    case 9:
    case 12:
    case 13:
      return 8;  // double, int64, uint64
    default:
      return 0;
  }
}

// The inflated bytes of a compressed element, read forward from its start in pieces: a sparse
// variable's index-array tags can lie megabytes in, and only those few bytes are needed.
class InflatedElement {
 public:
  InflatedElement(std::ifstream& in, std::uint64_t begin, std::uint32_t packed_bytes)
      : in_(in), next_packed_(begin), packed_end_(begin + packed_bytes) {
    ok_ = inflateInit(&z_) == Z_OK;
  }
  ~InflatedElement() {
    if (ok_) inflateEnd(&z_);
  }
  InflatedElement(const InflatedElement&) = delete;
  InflatedElement& operator=(const InflatedElement&) = delete;

  // The n bytes at `offset` of the inflated stream; offsets must not go back before an earlier
  // read's. False past the stream's end or on a corrupt stream.
  bool read(std::uint64_t offset, unsigned char* out, std::size_t n) {
    if (offset < window_start_) return false;
    while (offset + n > window_start_ + window_.size()) {
      if (offset > window_start_ + window_.size()) {  // nothing before `offset` is needed again
        window_start_ += window_.size();
        window_.clear();
      }
      if (!inflate_more()) return false;
    }
    std::memcpy(out, window_.data() + (offset - window_start_), n);
    const std::size_t done = static_cast<std::size_t>(offset - window_start_);
    window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(done));
    window_start_ = offset;
    return true;
  }

 private:
  bool inflate_more() {
    if (!ok_ || finished_) return false;
    if (z_.avail_in == 0) {
      const std::uint64_t take = std::min<std::uint64_t>(packed_.size(), packed_end_ - next_packed_);
      if (take == 0) return false;
      in_.clear();
      in_.seekg(static_cast<std::streamoff>(next_packed_));
      in_.read(reinterpret_cast<char*>(packed_.data()), static_cast<std::streamsize>(take));
      if (static_cast<std::uint64_t>(in_.gcount()) != take) return false;
      next_packed_ += take;
      z_.next_in = packed_.data();
      z_.avail_in = static_cast<uInt>(take);
    }
    unsigned char plain[1 << 14];
    z_.next_out = plain;
    z_.avail_out = sizeof plain;
    const int status = inflate(&z_, Z_SYNC_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) return false;
    finished_ = status == Z_STREAM_END;
    const std::size_t have = sizeof plain - z_.avail_out;
    window_.insert(window_.end(), plain, plain + have);
    return have > 0 || z_.avail_in == 0;
  }

  std::ifstream& in_;
  std::uint64_t next_packed_, packed_end_;
  z_stream z_{};
  bool ok_ = false, finished_ = false;
  std::vector<unsigned char> packed_ = std::vector<unsigned char>(1 << 16);
  std::vector<unsigned char> window_;
  std::uint64_t window_start_ = 0;
};

// libmatio allocates what a header claims before checking it against the file: a v5 dims tag
// of 4 GB made Mat_VarReadInfo ask for 8 GB, a v4 name length of 1.7 GB as much, a tag inside
// a compressed (v7) element 2.5 GB. So the headers are walked first and a size claiming more
// bytes than the file (or the enclosing element) holds is refused; inside a compressed element,
// whose true size is unknown until inflated, more than zlib's maximal expansion (1032:1) of it.
class MatHeaderCheck {
 public:
  explicit MatHeaderCheck(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    in_.seekg(0, std::ios::end);
    size_ = in_ ? static_cast<std::uint64_t>(in_.tellg()) : 0;
  }

  void run() {
    unsigned char header[4];
    if (size_ >= 128 && read_at(124, header, 4) && ((header[2] == 'I' && header[3] == 'M') || (header[2] == 'M' && header[3] == 'I'))) {
      swap_ = header[2] == 'M';
      if (word16(header) == 0x0100) return check_elements(128, size_, 0);
      if (word16(header) == 0x0200) return;  // v7.3, an HDF5 file
    }
    check_v4_records();  // libmatio reads any other file as v4
  }

 private:
  static constexpr std::uint32_t kMatrix = 14;
  static constexpr std::uint64_t kMaxSparseDimension = matrix_file::kMaxDimension;
  static constexpr std::uint32_t kCompressed = 15;
  static constexpr std::uint32_t kMinVariableBytes = 40;  // array flags 16, dims tag and 2 dims 16, name tag 8
  static constexpr std::uint64_t kMaxZlibRatio = 1032;
  static constexpr std::uint32_t kInt32 = 5, kUint32 = 6;
  static constexpr std::uint32_t kSparseClass = 5, kComplexFlag = 0x0800;
  // From a matrix element's tag: its tag (8), the array flags (8 + 8), the dims tag's type (4).
  static constexpr std::size_t kDimsSizeAt = 28;

  // Inflates the first 4 KB of a compressed element (the matrix tag and its header
  // sub-elements) and checks their sizes against the element's largest possible expansion.
  void check_compressed(std::uint64_t begin, std::uint32_t bytes) {
    std::string packed(std::min<std::uint32_t>(bytes, 1u << 16), '\0');
    if (!read_at(begin, reinterpret_cast<unsigned char*>(packed.data()), packed.size())) return;
    unsigned char plain[4096];
    z_stream z{};
    if (inflateInit(&z) != Z_OK) return;
    z.next_in = reinterpret_cast<Bytef*>(packed.data());
    z.avail_in = static_cast<uInt>(packed.size());
    z.next_out = plain;
    z.avail_out = sizeof plain;
    inflate(&z, Z_SYNC_FLUSH);  // whatever came out; a corrupt stream is matio's to report
    const std::size_t have = sizeof plain - z.avail_out;
    inflateEnd(&z);
    if (have < 8) return;
    const std::uint64_t limit = std::uint64_t{bytes} * kMaxZlibRatio;
    const std::uint32_t matrix_bytes = word32(plain + 4);
    if (word32(plain) != kMatrix) return;
    if (matrix_bytes > limit) fail_compressed(begin, matrix_bytes, limit);
    // libmatio reads the dims size at a fixed place (after the 16 bytes of array flags) whatever
    // the tags before it say, so check it there too.
    if (have >= kDimsSizeAt + 4 && word32(plain + kDimsSizeAt) > matrix_bytes)
      fail_compressed(begin, word32(plain + kDimsSizeAt), matrix_bytes);
    if (matrix_bytes > 0 && have >= 16)
      check_array_flags("byte 8 of the compressed element at byte " + std::to_string(begin - 8), word32(plain + 8), word32(plain + 12));
    check_dims_product("byte 0 of the compressed element at byte " + std::to_string(begin - 8), plain + 8, have - 8, matrix_bytes);
    for (std::size_t at = 8; at + 8 <= have;) {
      const std::uint32_t type = word32(plain + at), sub_bytes = word32(plain + at + 4);
      const std::string where = "byte " + std::to_string(at) + " of the compressed element at byte " + std::to_string(begin - 8);
      if (type >> 16) {
        check_sub_element(where, type & 0xffffu, type >> 16);
        at += 8;
        continue;
      }
      check_sub_element(where, type, sub_bytes);
      if (sub_bytes > matrix_bytes - (at - 8)) fail_compressed(begin, sub_bytes, matrix_bytes - (at - 8));
      at += 8 + (sub_bytes + 7u) / 8u * 8u;
    }
    if (matrix_bytes >= 16 && have >= 24 && (word32(plain + 16) & 0xffu) == kSparseClass) {
      InflatedElement inflated(in_, begin, bytes);
      check_sparse_arrays("byte 0 of the compressed element at byte " + std::to_string(begin - 8), matrix_bytes,
                          (word32(plain + 16) & kComplexFlag) != 0,
                          [&](std::uint64_t offset, unsigned char* out) { return inflated.read(8 + offset, out, 8); });
    }
  }
  // libmatio steps over a sub-element by its element count times its type's width, not by its
  // padded size: a type without a width, or a size that is no whole number of elements, puts
  // libmatio's reading position elsewhere than the file's layout, where it sizes allocations
  // from data bytes (fuzzing: a 4 GB calloc after a 2-byte sparse index array).
  void check_sub_element(const std::string& where, std::uint32_t type, std::uint32_t bytes) const {
    const unsigned width = v5_type_width(type);
    if (width == 0) fail(path_, "corrupt MAT file: the sub-element at " + where + " has the unknown data type " + std::to_string(type));
    if (bytes % width != 0)
      fail(path_, "corrupt MAT file: the sub-element at " + where + " holds " + std::to_string(bytes) + " bytes, not a whole number of " +
                      std::to_string(width) + "-byte elements");
  }
  // libmatio reads a matrix's array flags as 16 bytes whatever their tag says, then the next
  // sub-elements from there: flags of another size would again move it off the file's layout
  // (fuzzing: a 72-byte flags tag hid a reserved-type index array, and a 4 GB malloc). The
  // format fixes them as one miUINT32 pair.
  void check_array_flags(const std::string& where, std::uint32_t type, std::uint32_t bytes) const {
    if (type != 6 || bytes != 8)
      fail(path_, "corrupt MAT file: the array flags at " + where + " are of type " + std::to_string(type & 0xffffu) + " and " +
                      std::to_string(type >> 16 ? type >> 16 : bytes) + " bytes; the format requires miUINT32 (6) of 8 bytes");
  }
  // libmatio's Mat_VarReadInfo allocates a small numeric variable's data from its dimensions
  // before reading it: dims of 2 x 1.5e9 in a 221-byte file asked calloc for 24 GB (fuzzing,
  // issue 39). Every element but a sparse matrix's is stored in at least one byte (a cell's or a
  // struct's in a sub-matrix of 8 or more), so the dimensions' product cannot exceed the matrix's
  // bytes. `header` holds the matrix's array flags tag onwards (`have` bytes of it).
  void check_dims_product(const std::string& where, const unsigned char* header, std::size_t have, std::uint64_t matrix_bytes) const {
    static constexpr std::size_t kDimsAt = 24, kMaxDims = 32;  // after the flags (16) and the dims tag (8)
    if (have < kDimsAt || (word32(header + 8) & 0xffu) == kSparseClass || (word32(header + 16) >> 16) != 0) return;
    const std::uint32_t count = word32(header + 20) / 4;
    std::uint64_t product = 1;
    for (std::uint32_t k = 0; k < std::min<std::uint32_t>(count, kMaxDims) && kDimsAt + 4 * (k + 1) <= have; ++k) {
      const std::uint64_t dim = word32(header + kDimsAt + 4 * k);
      product = dim != 0 && product > matrix_bytes / dim ? matrix_bytes + 1 : product * dim;
    }
    if (product > matrix_bytes)
      fail(path_, "corrupt MAT file: the dimensions of the matrix at " + where + " make more elements than its " +
                      std::to_string(matrix_bytes) + " bytes can hold (each element takes at least one byte)");
  }
  // libmatio reads a sparse matrix's row indices and column starts as N / 4 elements of the type
  // their tag names (N its bytes) and steps on by what it read, so only 4-byte integers keep it on
  // the file's layout: 16-bit row indices left it inside them, where it took 0xffffffff as the
  // column starts' size and asked calloc for 4 GB (fuzzing, issue 39). It reads them, and the
  // values, wherever they follow, so all must be inside the matrix. `tag_at(offset, tag)` reads
  // the 8-byte tag `offset` bytes after the matrix's own tag.
  template <class TagAt>
  void check_sparse_arrays(const std::string& where, std::uint64_t matrix_bytes, bool complex, TagAt tag_at) const {
    static constexpr const char* kParts[] = {"array flags",   "dimensions", "name",           "row indices",
                                             "column starts", "values",     "imaginary parts"};
    const unsigned parts = complex ? 7 : 6;
    std::uint64_t offset = 0;
    for (unsigned part = 0; part < parts; ++part) {
      unsigned char tag[8];
      if (offset + 8 > matrix_bytes || !tag_at(offset, tag))
        fail(path_, "corrupt MAT file: the sparse matrix at " + where + " ends before its " + kParts[part] + " (the format stores " +
                        (complex ? "array flags, dimensions, name, row indices, column starts, values and imaginary parts)"
                                 : "array flags, dimensions, name, row indices, column starts and values)"));
      const std::uint32_t type = word32(tag), data_type = type & 0xffffu, small_bytes = type >> 16;
      if ((part == 3 || part == 4) && data_type != kInt32 && data_type != kUint32)
        fail(path_, "corrupt MAT file: the " + std::string(kParts[part]) + " of the sparse matrix at " + where + " are of type " +
                        std::to_string(data_type) + "; the format stores them as 32-bit integers, miINT32 (5) or miUINT32 (6)");
      offset += small_bytes ? 8 : 8 + (std::uint64_t{word32(tag + 4)} + 7u) / 8u * 8u;
    }
  }
  [[noreturn]] void fail_compressed(std::uint64_t begin, std::uint64_t claimed, std::uint64_t room) const {
    fail(path_, "corrupt MAT file: the compressed element at byte " + std::to_string(begin - 8) + " holds a tag of " +
                    std::to_string(claimed) + " bytes, at most " + std::to_string(room) + " fit");
  }

  bool read_at(std::uint64_t offset, unsigned char* out, std::size_t n) {
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n));
    return static_cast<std::size_t>(in_.gcount()) == n;
  }
  std::uint32_t word16(const unsigned char* b) const { return swap_ ? (b[0] << 8u) | b[1] : (b[1] << 8u) | b[0]; }
  std::uint32_t word32(const unsigned char* b) const {
    return swap_ ? (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | b[3]
                 : (std::uint32_t{b[3]} << 24) | (std::uint32_t{b[2]} << 16) | (std::uint32_t{b[1]} << 8) | b[0];
  }

  // The elements in [begin, end): each must fit; a matrix's sub-elements must fit in it.
  void check_elements(std::uint64_t begin, std::uint64_t end, int depth) {
    std::uint64_t at = begin;
    while (at + 8 <= end) {
      unsigned char tag[8];
      if (!read_at(at, tag, 8)) return;
      const std::uint32_t type = word32(tag), bytes = word32(tag + 4);
      if (type >> 16) {  // small data element: up to 4 bytes inside the tag
        if (depth > 0) check_sub_element("byte " + std::to_string(at), type & 0xffffu, type >> 16);
        at += 8;
        continue;
      }
      if (depth > 0) check_sub_element("byte " + std::to_string(at), type, bytes);
      if (bytes > end - at - 8)
        fail(path_, "corrupt MAT file: the element at byte " + std::to_string(at) + " claims " + std::to_string(bytes) + " bytes, " +
                        std::to_string(end - at - 8) + " remain");
      // libmatio reads a variable's array flags, dimensions and name tag (40 bytes at least)
      // whatever size its element claims, so a shorter one had it read the next element as its
      // own and allocate what that claimed: 4 GB (fuzzing, issue 39). Inside a cell or struct an
      // empty matrix (0 bytes) is valid; a variable is not.
      if (type == kMatrix && depth == 0 && bytes < kMinVariableBytes)
        fail(path_, "corrupt MAT file: the variable at byte " + std::to_string(at) + " claims " + std::to_string(bytes) +
                        " bytes, fewer than the " + std::to_string(kMinVariableBytes) + " of its array flags, dimensions and name");
      if (type == kMatrix && depth < 8) {
        unsigned char flags_tag[8];
        if (bytes > 0 && read_at(at + 8, flags_tag, 8))
          check_array_flags("byte " + std::to_string(at + 8), word32(flags_tag), word32(flags_tag + 4));
        unsigned char dims_size[4];
        if (bytes >= kDimsSizeAt - 4 && read_at(at + kDimsSizeAt, dims_size, 4) && word32(dims_size) > bytes)
          fail(path_, "corrupt MAT file: the matrix at byte " + std::to_string(at) + " claims dims of " +
                          std::to_string(word32(dims_size)) + " bytes in " + std::to_string(bytes));
        unsigned char header[64];
        const std::size_t have = std::min<std::uint64_t>(sizeof header, bytes);
        if (read_at(at + 8, header, have)) check_dims_product("byte " + std::to_string(at), header, have, bytes);
        check_elements(at + 8, at + 8 + bytes, depth + 1);
        unsigned char flags[4];
        if (bytes >= 16 && read_at(at + 16, flags, 4) && (word32(flags) & 0xffu) == kSparseClass)
          check_sparse_arrays("byte " + std::to_string(at), bytes, (word32(flags) & kComplexFlag) != 0,
                              [&](std::uint64_t offset, unsigned char* out) { return read_at(at + 8 + offset, out, 8); });
      }
      if (type == kCompressed && depth == 0) check_compressed(at + 8, bytes);
      // Sub-elements are padded to 8 bytes; top-level elements (compressed ones) are not.
      at += 8 + (depth > 0 ? (bytes + 7u) / 8u * 8u : bytes);
    }
  }

  // v4: records of a 20-byte header (type MOPT, rows, columns, imaginary flag, name length),
  // the name, then rows x columns elements (twice when complex).
  void check_v4_records() {
    std::uint64_t at = 0;
    while (at + 20 <= size_) {
      unsigned char h[20];
      if (!read_at(at, h, 20)) return;
      // As libmatio (Mat_VarReadNextInfo4), record by record: the type word is read in either
      // byte order (swapped when negative or above 4052), then the rest of the record in the order
      // its M digit names, 0 little-endian, 1 big-endian, whichever order the word itself was in.
      // Taking the word's own order instead let a big-endian word of M = 0 pass a name length of
      // 112 that libmatio read little-endian as 1.9 GB (fuzzing, issue 39).
      swap_ = false;
      std::uint32_t type = word32(h);
      if (type > 4052) {  // also a negative int32
        swap_ = true;
        type = word32(h);
      }
      swap_ = type / 1000 == 1;
      const std::uint32_t precision = type / 10 % 10;
      static constexpr std::uint64_t kWidth[] = {8, 4, 4, 2, 2, 1};
      if (type >= 2000 || precision > 5) {
        if (at == 0) return;  // not a v4 file: matio decides
        // libmatio would still allocate the name length this garbage claims, record after record.
        fail(path_, "corrupt MAT file: the v4 record at byte " + std::to_string(at) + " has the invalid type " + std::to_string(type));
      }
      const std::uint64_t name = word32(h + 16);
      const std::uint64_t data = std::uint64_t{word32(h + 4)} * word32(h + 8) * kWidth[precision] * (word32(h + 12) ? 2 : 1);
      const std::uint64_t remain = size_ - at - 20;
      if (name > remain || data > remain - name)
        fail(path_, "corrupt MAT file: the v4 record at byte " + std::to_string(at) + " claims " + std::to_string(name) + " + " +
                        std::to_string(data) + " bytes, " + std::to_string(remain) + " remain");
      if (type % 10 == 2) check_v4_sparse_size(at, at + 20 + name, word32(h + 4), word32(h + 8), precision);
      at += 20 + name + data;
    }
  }

  // A v4 sparse matrix is stored as rows of (i, j, value) ending with a row (m, n, 0) that gives
  // its size: libmatio allocates the n + 1 column pointers from that number, read from the data
  // (a 264-byte file asked for 3.94 GiB). So the size row is read and bounded here.
  void check_v4_sparse_size(std::uint64_t record, std::uint64_t data, std::uint32_t rows, std::uint32_t columns, std::uint32_t precision) {
    if (rows == 0 || columns < 3) return;  // libmatio reads no size row then
    for (std::uint32_t column = 0; column < 2; ++column) {
      double value = 0;
      if (!read_v4_number(data, (std::uint64_t{column} * rows + rows - 1), precision, value)) return;
      if (!(value >= 0 && value <= static_cast<double>(kMaxSparseDimension)))
        fail(path_, "corrupt MAT file: the v4 sparse record at byte " + std::to_string(record) + " claims " +
                        std::string(column == 0 ? "rows" : "columns") + " = " + number_text(value) + " (the limit is " +
                        std::to_string(kMaxSparseDimension) + ")");
    }
  }
  bool read_v4_number(std::uint64_t data, std::uint64_t index, std::uint32_t precision, double& value) {
    static constexpr unsigned kWidth[] = {8, 4, 4, 2, 2, 1};
    unsigned char b[8];
    if (!read_at(data + index * kWidth[precision], b, kWidth[precision])) return false;
    if (swap_) std::reverse(b, b + kWidth[precision]);
    switch (precision) {
      case 0: {
        double d;
        std::memcpy(&d, b, 8);
        value = d;
        break;
      }
      case 1: {
        float f;
        std::memcpy(&f, b, 4);
        value = f;
        break;
      }
      case 2: {
        std::int32_t i;
        std::memcpy(&i, b, 4);
        value = i;
        break;
      }
      case 3: {
        std::int16_t i;
        std::memcpy(&i, b, 2);
        value = i;
        break;
      }
      case 4: {
        std::uint16_t i;
        std::memcpy(&i, b, 2);
        value = i;
        break;
      }
      default:
        value = b[0];
    }
    return true;
  }

  const std::string& path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
  bool swap_ = false;
};

}  // namespace

void check_mat_headers(const std::string& path) { MatHeaderCheck(path).run(); }

}  // namespace hbtrack
