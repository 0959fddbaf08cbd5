#include "hbtrack/io/mat_file.hpp"
#include "hbtrack/io/matrix_market.hpp"

#include <gtest/gtest.h>
#include <matio.h>
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "matrix_file_test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_mat_file {

namespace {

using namespace hbtrack::test;  // TempDirTest, expect_error, example_matrix, sparse_from, fs

// Writes variables into a v5 .mat file the way MATLAB users would produce them.
class MatWriter {
 public:
  explicit MatWriter(const std::string& path, mat_ft version = MAT_FT_MAT5, matio_compression compression = MAT_COMPRESSION_NONE)
      : file_(Mat_CreateVer(path.c_str(), nullptr, version)), compression_(compression) {
    if (file_ == nullptr) throw std::runtime_error("cannot create " + path);
  }
  ~MatWriter() { Mat_Close(file_); }
  MatWriter(const MatWriter&) = delete;
  MatWriter& operator=(const MatWriter&) = delete;

  void dense(const std::string& name, Eigen::MatrixXd matrix) {
    size_t dims[2] = {static_cast<size_t>(matrix.rows()), static_cast<size_t>(matrix.cols())};
    write(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, matrix.data(), MAT_F_DONT_COPY_DATA));
  }

  template <class T>
  void typed(const std::string& name, matio_classes class_type, matio_types data_type, std::vector<T> column_major, size_t rows,
             size_t cols) {
    size_t dims[2] = {rows, cols};
    write(Mat_VarCreate(name.c_str(), class_type, data_type, 2, dims, column_major.data(), MAT_F_DONT_COPY_DATA));
  }

  void sparse(const std::string& name, Eigen::SparseMatrix<double> matrix) {
    matrix.makeCompressed();
    const auto nonzeros = static_cast<mat_uint32_t>(matrix.nonZeros());
    std::vector<mat_uint32_t> row_index(matrix.innerIndexPtr(), matrix.innerIndexPtr() + nonzeros);
    std::vector<mat_uint32_t> column_start(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.cols() + 1);
    std::vector<double> values(matrix.valuePtr(), matrix.valuePtr() + nonzeros);
    mat_sparse_t csc{};
    csc.nzmax = nonzeros;
    csc.ir = row_index.data();
    csc.nir = nonzeros;
    csc.jc = column_start.data();
    csc.njc = static_cast<mat_uint32_t>(column_start.size());
    csc.ndata = nonzeros;
    csc.data = values.data();
    size_t dims[2] = {static_cast<size_t>(matrix.rows()), static_cast<size_t>(matrix.cols())};
    write(Mat_VarCreate(name.c_str(), MAT_C_SPARSE, MAT_T_DOUBLE, 2, dims, &csc, MAT_F_DONT_COPY_DATA));
  }

  void complex(const std::string& name) {
    std::vector<double> real_part = {1.0, 2.0, 3.0, 4.0};
    std::vector<double> imaginary_part = {0.5, 0.0, -0.5, 1.0};
    mat_complex_split_t split{real_part.data(), imaginary_part.data()};
    size_t dims[2] = {2, 2};
    write(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &split, MAT_F_COMPLEX | MAT_F_DONT_COPY_DATA));
  }

  void three_dimensional(const std::string& name) {
    std::vector<double> values(8, 1.0);
    size_t dims[3] = {2, 2, 2};
    write(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 3, dims, values.data(), MAT_F_DONT_COPY_DATA));
  }

  void text(const std::string& name, std::string value) {
    size_t dims[2] = {1, value.size()};
    write(Mat_VarCreate(name.c_str(), MAT_C_CHAR, MAT_T_UINT8, 2, dims, value.data(), MAT_F_DONT_COPY_DATA));
  }

 private:
  void write(matvar_t* variable) {
    ASSERT_NE(variable, nullptr);
    EXPECT_EQ(Mat_VarWrite(file_, variable, compression_), 0);
    Mat_VarFree(variable);  // MAT_F_DONT_COPY_DATA: frees only matio's header, not our buffers
  }

  mat_t* file_;
  matio_compression compression_;
};

// ---------------------------------------------------------------------------------------------
// MATLAB .mat files

// A v5 file's 128-byte header (text, version 0x0100, little-endian "IM"), for elements written
// byte by byte.
std::string v5_header() {
  std::string header(128, ' ');
  header.replace(0, 10, "MATLAB 5.0");
  header.replace(124, 4, std::string("\x00\x01IM", 4));
  return header;
}

class MatFileTest : public TempDirTest {
 protected:
  // The bytes of a v5 file holding `matrix` as the sparse variable K, as libmatio writes it.
  std::string sparse_file_bytes(const std::string& filename, const Eigen::SparseMatrix<double>& matrix) const {
    const std::string path = path_for(filename);
    {
      MatWriter writer(path);
      writer.sparse("K", matrix);
    }
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  // A v5 file of a dense `rows` x `cols` variable K whose dims sub-element (tag miINT32 = 5, 8
  // bytes, then int32 rows, cols) gets `replacement` written at `offset` from the tag's start.
  std::string mat_with_patched_dims(const std::string& filename, int rows, int cols, std::size_t offset,
                                    const std::string& replacement) const {
    const std::string path = path_for(filename);
    {
      MatWriter writer(path);
      writer.dense("K", Eigen::MatrixXd::Ones(rows, cols));
    }
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    std::string dims_element("\x05\0\0\0\x08\0\0\0", 8);
    dims_element += std::string(reinterpret_cast<const char*>(&rows), 4);
    dims_element += std::string(reinterpret_cast<const char*>(&cols), 4);
    const std::size_t at = bytes.find(dims_element);
    EXPECT_NE(at, std::string::npos);
    if (at != std::string::npos) bytes.replace(at + offset, replacement.size(), replacement);
    return write_text(filename, bytes);
  }
};

TEST_F(MatFileTest, ReadsDenseAndSparseIdenticallyToMatrixMarket) {
  const Eigen::MatrixXd dense = example_matrix();
  const std::string mat_path = path_for("model.mat");
  {
    MatWriter writer(mat_path);
    writer.dense("K_dense", dense);
    writer.sparse("K_sparse", sparse_from(dense));
  }
  const std::string mtx_path = path_for("model.mtx");
  hbtrack::write_matrix_market(mtx_path, sparse_from(dense));

  const Eigen::MatrixXd from_dense = hbtrack::read_mat_variable(mat_path, "K_dense");
  const Eigen::MatrixXd from_sparse = hbtrack::read_mat_variable(mat_path, "K_sparse");
  const Eigen::MatrixXd from_mtx = hbtrack::read_matrix_market(mtx_path);
  EXPECT_EQ(from_dense, dense);
  EXPECT_EQ(from_sparse, dense);
  EXPECT_EQ(from_mtx, dense);

  const Eigen::SparseMatrix<double> sparse = hbtrack::read_mat_variable_sparse(mat_path, "K_sparse");
  EXPECT_EQ(sparse.rows(), 3);
  EXPECT_EQ(sparse.cols(), 4);
  EXPECT_EQ(sparse.nonZeros(), 6);
  EXPECT_EQ(Eigen::MatrixXd(hbtrack::read_mat_variable_sparse(mat_path, "K_dense")), dense);
}

TEST_F(MatFileTest, ReadsV4CompressedV7AndV73Files) {
  const Eigen::MatrixXd dense = example_matrix();
  struct Format {
    const char* filename;
    mat_ft version;
    matio_compression compression;
  };
  for (const Format& format : {Format{"v4.mat", MAT_FT_MAT4, MAT_COMPRESSION_NONE}, Format{"v7.mat", MAT_FT_MAT5, MAT_COMPRESSION_ZLIB},
                               Format{"v73.mat", MAT_FT_MAT73, MAT_COMPRESSION_NONE}}) {
    SCOPED_TRACE(format.filename);
    const std::string path = path_for(format.filename);
    mat_t* probe = Mat_CreateVer(path.c_str(), nullptr, format.version);
    if (probe == nullptr) continue;  // v7.3 needs libmatio built with HDF5
    Mat_Close(probe);
    {
      MatWriter writer(path, format.version, format.compression);
      writer.dense("D", dense);
      writer.sparse("S", sparse_from(dense));
    }
    EXPECT_EQ(hbtrack::read_mat_variable(path, "D"), dense);
    EXPECT_EQ(hbtrack::read_mat_variable(path, "S"), dense);
  }
}

TEST_F(MatFileTest, VectorsKeepTheirOrientation) {
  const std::string path = path_for("vectors.mat");
  {
    MatWriter writer(path);
    writer.dense("column", Eigen::VectorXd::LinSpaced(4, 1.0, 4.0));
    writer.dense("row", Eigen::RowVectorXd::LinSpaced(3, 1.0, 3.0));
  }
  const Eigen::MatrixXd column = hbtrack::read_mat_variable(path, "column");
  const Eigen::MatrixXd row = hbtrack::read_mat_variable(path, "row");
  EXPECT_EQ(column.rows(), 4);
  EXPECT_EQ(column.cols(), 1);
  EXPECT_EQ(row.rows(), 1);
  EXPECT_EQ(row.cols(), 3);
  EXPECT_EQ(column(3, 0), 4.0);
  EXPECT_EQ(row(0, 2), 3.0);
}

TEST_F(MatFileTest, ConvertsSingleAndIntegerClassesToDouble) {
  const std::string path = path_for("classes.mat");
  {
    MatWriter writer(path);
    writer.typed<float>("single", MAT_C_SINGLE, MAT_T_SINGLE, {1.5f, -2.0f, 0.0f, 4.25f}, 2, 2);
    writer.typed<std::int32_t>("int32", MAT_C_INT32, MAT_T_INT32, {1, -2, 0, 40000}, 2, 2);
    writer.typed<std::uint8_t>("uint8", MAT_C_UINT8, MAT_T_UINT8, {255, 0, 1, 2}, 2, 2);
  }
  Eigen::MatrixXd single(2, 2), int32(2, 2), uint8(2, 2);
  single << 1.5, 0.0, -2.0, 4.25;
  int32 << 1, 0, -2, 40000;
  uint8 << 255, 1, 0, 2;
  EXPECT_EQ(hbtrack::read_mat_variable(path, "single"), single);
  EXPECT_EQ(hbtrack::read_mat_variable(path, "int32"), int32);
  EXPECT_EQ(hbtrack::read_mat_variable(path, "uint8"), uint8);
}

TEST_F(MatFileTest, MissingFileIsReported) {
  const std::string path = path_for("missing.mat");
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path, "cannot open file");
}

TEST_F(MatFileTest, NonMatFileIsReported) {
  const std::string path = write_text("text.mat", "this is not a MAT file, just text\n");
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path, "not a readable MAT file");
}

TEST_F(MatFileTest, MissingVariableListsAvailableNames) {
  const std::string path = path_for("names.mat");
  {
    MatWriter writer(path);
    writer.dense("M", Eigen::MatrixXd::Identity(2, 2));
    writer.dense("K2", Eigen::MatrixXd::Identity(2, 2));
  }
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path, "variable 'K': not found; available: M, K2");
  expect_error([&] { hbtrack::read_mat_variable_sparse(path, "K"); }, path, "not found");
}

TEST_F(MatFileTest, ComplexVariableIsRejected) {
  const std::string path = path_for("complex.mat");
  {
    MatWriter writer(path);
    writer.complex("Z");
  }
  expect_error([&] { hbtrack::read_mat_variable(path, "Z"); }, path, "variable 'Z': is complex");
}

TEST_F(MatFileTest, ThreeDimensionalVariableIsRejected) {
  const std::string path = path_for("cube.mat");
  {
    MatWriter writer(path);
    writer.three_dimensional("C");
  }
  expect_error([&] { hbtrack::read_mat_variable(path, "C"); }, path, "variable 'C': has 3 dimensions");
}

TEST_F(MatFileTest, CharVariableIsRejected) {
  const std::string path = path_for("char.mat");
  {
    MatWriter writer(path);
    writer.text("label", "stiffness");
  }
  expect_error([&] { hbtrack::read_mat_variable(path, "label"); }, path, "variable 'label': is a char array");
}

TEST_F(MatFileTest, NonFiniteValueIsRejected) {
  const std::string path = path_for("nan.mat");
  {
    MatWriter writer(path);
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(2, 2);
    matrix(1, 0) = std::numeric_limits<double>::infinity();
    writer.dense("K", matrix);
  }
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path, "variable 'K': non-finite value at (2, 1)");
}

// A corrupt dimension must be caught from the header, before libmatio allocates what it claims.
TEST_F(MatFileTest, ImplausibleSizeInHeaderIsRejected) {
  const std::string four_million("\x00\x09\x3d\x00", 4);  // 4'000'000 little-endian, within the dimension limit
  const std::string path = mat_with_patched_dims("corrupt_dims.mat", 2, 3, 12, four_million);
  // Refused by the header check, before libmatio allocates from those dims (its 96 bytes cannot
  // hold 8e6 elements), rather than after it by the reader's "header claims 2 x 4000000".
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "the dimensions of the matrix at byte 128 make more elements than its 96 bytes can hold");
}

// Fuzzing finding (build-fuzz/findings/mat_file/oom-1145...): a dims tag claiming 4 GB made
// libmatio's Mat_VarReadInfo allocate 8 GB before any check of ours could run.
TEST_F(MatFileTest, TagClaimingMoreBytesThanTheFileIsRejectedBeforeMatio) {
  // 4294967047 bytes in the dims tag, as the fuzzer wrote it.
  const std::string path = mat_with_patched_dims("huge_tag.mat", 2, 2, 4, std::string("\x07\xff\xff\xff", 4));
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "corrupt MAT file: the matrix at byte 128 claims dims of 4294967047 bytes");
}

// Fuzzing finding (oom-377bc906): a sparse matrix whose row-index array has a reserved data type
// (or a size that is no whole number of indices) moved libmatio's reading position off the
// file's layout, and it sized a 4 GB calloc from data bytes. Both are refused from the header.
TEST_F(MatFileTest, SparseIndexArrayOfUnknownTypeOrPartialSizeIsRejected) {
  Eigen::SparseMatrix<double> matrix(2, 2);
  matrix.insert(0, 0) = 2.0;
  matrix.insert(1, 1) = -1.0;
  const std::string clean = sparse_file_bytes("sparse_clean.mat", matrix);
  // The row-index tag (libmatio writes uint32) follows the dims (2 x 2, int32) and the name 'K' (one small element).
  const std::string dims("\x05\0\0\0\x08\0\0\0\x02\0\0\0\x02\0\0\0", 16);
  const std::size_t dims_at = clean.find(dims);
  ASSERT_NE(dims_at, std::string::npos);
  const std::size_t index_tag_at = dims_at + dims.size() + 8;
  ASSERT_EQ(clean.substr(index_tag_at, 8), std::string("\x06\0\0\0\x08\0\0\0", 8)) << "two uint32 row indices expected";

  std::string reserved_type = clean;
  reserved_type[index_tag_at] = '\x08';  // miRESERVED, as the fuzzer wrote it
  const std::string reserved_path = write_text("sparse_reserved_type.mat", reserved_type);
  expect_error([&] { hbtrack::read_mat_variable(reserved_path, "K"); }, reserved_path,
               "corrupt MAT file: the sub-element at byte " + std::to_string(index_tag_at) + " has the unknown data type 8");

  std::string partial = clean;
  partial[index_tag_at + 4] = '\x06';  // 6 bytes: one and a half uint32 indices
  const std::string partial_path = write_text("sparse_partial_index.mat", partial);
  expect_error([&] { hbtrack::read_mat_variable(partial_path, "K"); }, partial_path,
               "holds 6 bytes, not a whole number of 4-byte elements");
}

// Fuzzing finding (oom-88432803): array flags whose tag claimed 72 bytes. libmatio reads the
// flags as 16 bytes whatever the tag says, so the walk of the sub-elements and libmatio's reading
// parted ways and a reserved-type index array behind the flags went unchecked (a 4 GB malloc).
TEST_F(MatFileTest, ArrayFlagsOfAnotherSizeThanTheFormatsAreRejected) {
  const std::string clean_path = path_for("flags_clean.mat");
  {
    MatWriter writer(clean_path);
    writer.dense("K", Eigen::MatrixXd::Ones(2, 2));
  }
  std::ifstream in(clean_path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string flags_tag("\x06\0\0\0\x08\0\0\0", 8);
  const std::size_t at = bytes.find(flags_tag, 128);
  ASSERT_EQ(at, 136u) << "the first matrix's array flags follow its tag";
  bytes[at + 4] = '\x48';  // 72 bytes, as the fuzzer wrote it
  const std::string path = write_text("flags_72.mat", bytes);
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "corrupt MAT file: the array flags at byte 136 are of type 6 and 72 bytes; the format requires miUINT32 (6) of 8 bytes");
}

// Fuzzing finding (timeout-95af...): a header of 1e8 columns made the reader zero index arrays
// for over 30 s under the sanitizers; the dimension limit is now 5e6.
TEST_F(MatFileTest, DimensionAboveTheLimitIsRejected) {
  const std::string path = mat_with_patched_dims("wide.mat", 2, 3, 12, std::string("\x00\xe1\xf5\x05", 4));  // 100'000'000
  // The header check refuses it first (96 bytes cannot hold 2e8 elements); the reader's limit
  // of 5e6 per dimension stays for files large enough to hold what their dims claim.
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "the dimensions of the matrix at byte 128 make more elements than its 96 bytes can hold");
}

// Fuzzing finding (oom-0338...): inside a compressed (v7) element, a tag claiming 2.5 GB that
// libmatio allocated on inflating. The element as the fuzzer wrote it, after a v5 header.
TEST_F(MatFileTest, CompressedTagBeyondZlibsExpansionIsRejectedBeforeMatio) {
  const std::string header = v5_header();
  const std::string element(
      "\x0f\x00\x00\x00\x2e\x00\x00\x00\x78\x9c\xe3\x63\x60\x60\x08\x00\x62\x35\x20\xe6\x80\xd2\x20\xc0"
      "\x0a\xe5\x32\x41\x31\x23\x10\x7a\x03\x69\x4e\x20\x56\x60\x80\x03\x07\x08\xf5\x61\x3f\x2a\xcd\xe0"
      "\x00\x00\x70\xa0\x04\xd8\x0f\x00\x00\x78\x00\x2c\x00\x00\x00\x9c\x5d\x78\x03\x5a",
      68);
  const std::string path = write_text("compressed_tag.mat", header + element);
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path, "corrupt MAT file: the compressed element at byte 128 holds a tag of");
}

// Fuzzing finding (oom-dcc1...): the same, but with tags that libmatio does not read as tags:
// it takes the dims size at a fixed place after the array flags.
TEST_F(MatFileTest, CompressedDimsSizeAtItsFixedPlaceIsChecked) {
  const std::string header = v5_header();
  const std::string element(
      "\x0f\x00\x00\x00\x2e\x00\x00\x00\x78\x9c\xe3\x63\x60\x60\x08\x00\x62\x35\x20\xe6\x80\xd2\x20\xc0"
      "\x0a\xe5\x32\x41\x31\x23\x10\x7a\x03\x69\xab\xdf\xa9\x9f\x7f\xfc\xf8\xf7\xf5\x61\x3f\x2a\xcd\xe0"
      "\x00\x00\x70\xa0\x04\xd8\x0f\x00\x00\x78\x00\x2c\x00\xcb\xcb\xcb\xcb\xcb\xcb\xd4\x00\x00\x9c\x32"
      "\x5d\x78\x03\x5a",
      76);
  const std::string path = write_text("compressed_dims.mat", header + element);
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "corrupt MAT file: the compressed element at byte 128 holds a tag of 637534208");
}

// Fuzzing finding (timeout-0d48...): a valid v4 record followed by garbage whose bytes 124-127
// look like a v5 header of an unknown version; libmatio reads it as v4 and allocated the name
// lengths the garbage claims, record after record (over 30 s). The input as the fuzzer wrote it.
TEST_F(MatFileTest, GarbageAfterAV4RecordIsRejectedBeforeMatio) {
  const std::string bytes(
      "\x00\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x00\x00\x00\x00\x00\x1e\x00\x00\x00\x01\x00\x00\x00"
      "\x00\x00\x00\x00\x00\x40\x00\xc9\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff"
      "\xff\xff\xff\xff\xff\xff\xff\xdf\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff\xff"
      "\xff\xff\xff\xff\xff\xff\xff\xff\x00\x00\x00\x00\x00\x00\x01\x65\x00\x00\x00\x00\x00\x00\x01\x00"
      "\x00\x00\x05\x00\x00\x00\x0c\x00\x00\x00\x00\x00\x00\x00\x02\x00\x00\x00\x04\x00\x00\x00\x00\x00"
      "\x00\x00\x09\x00\x40\x01\x49\x4d\x0e\x00\x00\x00\x80\x00\x00\x00\x06\x00\x00\x00\x08\x00\x00\x00"
      "\x05\x00\x00\x00\x04\x00\x00\x00\x05\x00\x00\x00\x08\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x00"
      "\x01\x00\x01\x00\x4b\x00\x00\x00\x05\x00\x00\x00\x10\x00\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00"
      "\x00\x72\x72\x72\x72\x00\x00\x00\x01\x00\x02\x00\x05\x00\x00\x00\x0c\x00\x00\x00\x00\x00\x00\x00"
      "\x00\x00\x00\x02\x04\x00\x00\x00\x00\x00\x00\x00\x09\x00\x00\x00\x20\x00\x00\x00\x00\x00\x00\x00"
      "\x00\x00\x00\x40\x00\x00\x00\x00\x00\x00\xf0\xbf\x00\x00\x00\x00\x00\x00\xf0\xbf\x00\x00\x00\x00"
      "\x00\x00\x00\x40",
      268);
  const std::string path = write_text("v4_garbage.mat", bytes);
  // Its type word at byte 107 is a sparse matrix's (2) stored big-endian, so the record is read
  // little-endian, as libmatio reads it (M = 0), and its name length is the garbage's 1.2 GB.
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "corrupt MAT file: the v4 record at byte 107 claims 1224818688 + 0 bytes");
}

// Fuzzing finding (oom-1e5f...): a v4 record whose name length claims 1.7 GB.
TEST_F(MatFileTest, V4NameLengthBeyondTheFileIsRejectedBeforeMatio) {
  const std::string path = path_for("huge_name.mat");
  {
    MatWriter writer(path, MAT_FT_MAT4);
    writer.dense("K", Eigen::MatrixXd::Ones(2, 2));
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  ASSERT_GE(bytes.size(), 20u);
  bytes.replace(16, 4, std::string("\x78\x61\x62\x69", 4));  // name length 1768055160
  write_text("huge_name.mat", bytes);
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path, "corrupt MAT file: the v4 record at byte 0 claims 1768055160");
}

// Fuzzing finding (oom-2f72...): a 106-byte v4 sparse record of one entry whose last row (the
// sparse format's size row) makes it some 26 000 x 26 000; its dense copy, within the old limit of
// 1e9 entries, allocated 5.6 GB. Dense copies now stop at 4000 x 4000 entries (128 MB); the
// sparse reader still reads it.
TEST_F(MatFileTest, DenseCopyOfAHugeSparseRecordIsRejected) {
  const std::string bytes(
      "\x02\x00\x00\x00\x03\x00\x00\x00\x03\x00\x00\x00\x00\x00\x00\x00\x02\x00\x00\x00\x4b\x00\x00\x00"
      "\x00\x00\x00\x00\xf0\x3f\x00\x00\x00\x00\x00\x00\x00\x40\x00\x00\x00\x00\x00\x00\xbd\x40\x00\x00"
      "\x00\x00\x00\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\xfe\xf6\x40\x00\xff"
      "\xff\x08\xff\x00\x20\x41\x80\x45\xcf\x00\x00\x00\x20\x41\x80\x45\x01\x00\x00\x00\x00\x64\x01\xfe"
      "\x00\x00\x00\x00\x00\x49\x00\x00\x01\x00",
      106);
  const std::string path = write_text("dense_copy.mat", bytes);
  EXPECT_NO_THROW(hbtrack::read_mat_variable_sparse(path, "K"));
  expect_error([&] { hbtrack::read_mat_variable(path, "K"); }, path,
               "is too large to read as a dense matrix (limit 16000000 entries, 128 MB)");
}

// Fuzzing finding (oom-dba0...): a v4 type word stored big-endian whose M digit says little-endian
// (0). libmatio reads the rest of the record in the order M names, so the name length 0x70 the
// header check read big-endian was 1.9 GB to libmatio, which allocated it.
TEST_F(MatFileTest, V4RecordIsReadInTheByteOrderOfItsMDigit) {
  const std::string header("\x00\x00\x00\x01\x00\x00\x00\x08\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x70", 20);
  const std::string path = write_text("m0_big_endian.mat", header + std::string(112, '\0'));
  expect_error([&] { hbtrack::read_mat_variable_sparse(path, "K"); }, path,
               "corrupt MAT file: the v4 record at byte 0 claims 1879048192 + 0 bytes, 112 remain");
}

// Fuzzing finding (oom-cfce...): a variable (miMATRIX) of 0 bytes at the top level; libmatio
// read the elements after it as its array flags, dimensions and data, and allocated 4 GB. The
// elements as the fuzzer wrote them, after a v5 header.
TEST_F(MatFileTest, VariableTooShortForItsHeaderIsRejectedBeforeMatio) {
  const std::string header = v5_header();
  const std::string elements(
      "\x0e\x00\x00\x00\x00\x00\x00\x00\x06\x00\x00\x00\x08\x00\x00\x00\x05\x00\x00\x00\x04\x00\x00\x00"
      "\x05\x00\x00\x00\x08\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x00\x01\x00\x01\x00\x4b\x00\x00\x00"
      "\x02\x00\x00\x00\x00\x00\x00\x00\x02\x00\x00\x00\x4b\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00"
      "\x05\x00\x00\x00\x22\x31\x41\x33\x0c\x00\x00\x00\x00\x00\x00\x00\x02\x00\x00\x00\xff\xff\xff\xff"
      "\xff\xff\xff\x00\x00\x00\x00\x00\x00\x00\x00\x00\x1c\x1c\x1c\x1c\x1c\x00\x40\x00\x00\x00\x00\x00"
      "\x00\xf0\xbf\x00\x00\x00\x00\x00\x00\xf0\xbf\x00\x00\x00\x00\x00\x00\x00\x05\x00\x00\x00\x00\x40",
      144);
  const std::string path = write_text("empty_variable.mat", header + elements);
  expect_error([&] { hbtrack::read_mat_variable_sparse(path, "K"); }, path,
               "corrupt MAT file: the variable at byte 128 claims 0 bytes, fewer than the 40 of its array flags, dimensions and name");
}

// Fuzzing finding (oom-9354...): a sparse variable whose row indices are stored as miINT16.
// libmatio reads N / 4 of them for an N-byte array and steps on by the 8 bytes it read, so it
// took the indices' last bytes (0xffffffff) as the column starts' size and called calloc for
// 4 GB. The 264-byte file as the fuzzer wrote it (fuzz/seeds/mat_file/regression-v5-sparse-int16-indices.mat).
TEST_F(MatFileTest, SparseIndicesOfOtherThan32BitsAreRejectedBeforeMatio) {
  const std::string elements(
      "\x0e\x00\x00\x00\x80\x00\x00\x00\x06\x00\x00\x00\x08\x00\x00\x00\x05\x00\x00\x00\x04\x00\x00\x00"
      "\x05\x00\x00\x00\x08\x00\x00\x00\x02\x00\x00\x00\x02\x00\x00\x00\x01\x00\x01\x00\x4b\x00\x00\x00"
      "\x03\x00\x00\x00\x10\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00\x04\x00\x00\x00\xff\xff\xff\xff"
      "\x03\x00\x00\x00\x0c\x00\x00\x00\x00\x00\x00\x00\x02\x00\x00\x00\xff\xff\xff\xff\xff\xff\xff\xff"
      "\x01\x00\x00\x00\x20\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x40\x00\x00\x00\x00\x00\x00\xf0\xbf"
      "\x00\x00\x00\x00\x00\x00\xf0\xbf\x00\x00\x00\x00\x00\x00\x00\x40",
      136);
  const std::string path = write_text("sparse_int16_indices.mat", v5_header() + elements);
  for (const bool dense : {false, true})
    expect_error([&] { dense ? (void)hbtrack::read_mat_variable(path, "K") : (void)hbtrack::read_mat_variable_sparse(path, "K"); }, path,
                 "corrupt MAT file: the row indices of the sparse matrix at byte 128 are of type 3; the format stores them as 32-bit "
                 "integers, miINT32 (5) or miUINT32 (6)");
}

// A double matrix of 2 x 1493172226 in 80 bytes: libmatio's Mat_VarReadInfo asked calloc for
// 24 GB before reading its data (fuzzing, issue 39; the fuzzer's input is
// fuzz/seeds/mat_file/regression-v5-dims-of-24-gb.mat). Each element takes a byte at least.
TEST_F(MatFileTest, DimensionsBeyondTheVariablesBytesAreRejectedBeforeMatio) {
  const std::string elements = std::string(
                                   "\x0e\x00\x00\x00\x50\x00\x00\x00\x06\x00\x00\x00\x08\x00\x00\x00"
                                   "\x06\x00\x00\x00\x00\x00\x00\x00\x05\x00\x00\x00\x08\x00\x00\x00"
                                   "\x02\x00\x00\x00\x02\x00\x00\x59\x01\x00\x01\x00\x4b\x00\x00\x00"
                                   "\x09\x00\x00\x00\x20\x00\x00\x00",
                                   56) +
                               std::string(32, '\0');
  const std::string path = write_text("dims_of_24_gb.mat", v5_header() + elements);
  for (const bool dense : {false, true})
    expect_error([&] { dense ? (void)hbtrack::read_mat_variable(path, "K") : (void)hbtrack::read_mat_variable_sparse(path, "K"); }, path,
                 "corrupt MAT file: the dimensions of the matrix at byte 128 make more elements than its 80 bytes can hold (each element "
                 "takes at least one byte)");
}

// The same rule inside a compressed (v7) variable, and the arrays libmatio reads wherever they
// follow: a sparse matrix cut short before its values would have it read the next element's.
TEST_F(MatFileTest, SparseArraysAreCheckedWhenCompressedAndMustAllBeThere) {
  Eigen::SparseMatrix<double> matrix(3, 3);
  matrix.insert(0, 0) = 2.0;
  matrix.insert(2, 1) = -1.0;
  const std::string matio_compressed_path = path_for("sparse_matio_compressed.mat");
  {
    MatWriter writer(matio_compressed_path, MAT_FT_MAT5, MAT_COMPRESSION_ZLIB);
    writer.sparse("K", matrix);
  }
  EXPECT_EQ(hbtrack::read_mat_variable_sparse(matio_compressed_path, "K").nonZeros(), 2) << "a valid compressed sparse variable loads";

  const std::string clean = sparse_file_bytes("sparse_whole.mat", matrix);
  const std::string row_indices("\x06\0\0\0\x08\0\0\0\0\0\0\0\x02\0\0\0", 16);                        // 0 2 as uint32
  const std::string column_starts("\x06\0\0\0\x10\0\0\0\0\0\0\0\x01\0\0\0\x02\0\0\0\x02\0\0\0", 24);  // 0 1 2 2
  const std::size_t row_indices_at = clean.find(row_indices), column_starts_at = clean.find(column_starts);
  ASSERT_NE(row_indices_at, std::string::npos);
  ASSERT_NE(column_starts_at, std::string::npos);

  // The variable (after the 128-byte header) deflated into one miCOMPRESSED element.
  const auto compressed = [&](const std::string& file_bytes) {
    const std::string variable = file_bytes.substr(128);
    uLongf packed_size = compressBound(static_cast<uLong>(variable.size()));
    std::string packed(packed_size, '\0');
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(variable.data()),
                        static_cast<uLong>(variable.size()), Z_BEST_COMPRESSION),
              Z_OK);
    const std::uint32_t tag[2] = {15, static_cast<std::uint32_t>(packed_size)};
    return file_bytes.substr(0, 128) + std::string(reinterpret_cast<const char*>(tag), 8) + packed.substr(0, packed_size);
  };
  const std::string deflated_path = write_text("sparse_deflated.mat", compressed(clean));
  EXPECT_EQ(hbtrack::read_mat_variable_sparse(deflated_path, "K").nonZeros(), 2) << "the hand-deflated variable loads";

  std::string int16_rows = clean;
  int16_rows[row_indices_at] = '\x03';
  const std::string compressed_int16_path = write_text("sparse_compressed_int16_rows.mat", compressed(int16_rows));
  expect_error([&] { hbtrack::read_mat_variable_sparse(compressed_int16_path, "K"); }, compressed_int16_path,
               "corrupt MAT file: the row indices of the sparse matrix at byte 0 of the compressed element at byte 128 are of type 3");

  std::string int16_starts = clean;
  int16_starts[column_starts_at] = '\x03';
  const std::string int16_path = write_text("sparse_int16_starts.mat", int16_starts);
  expect_error([&] { hbtrack::read_mat_variable_sparse(int16_path, "K"); }, int16_path,
               "the column starts of the sparse matrix at byte 128 are of type 3");

  std::string cut = clean.substr(0, column_starts_at + column_starts.size());
  const auto cut_bytes = static_cast<std::uint32_t>(cut.size() - 136);  // after the header (128) and the variable's tag
  cut.replace(132, 4, std::string(reinterpret_cast<const char*>(&cut_bytes), 4));
  const std::string cut_path = write_text("sparse_without_values.mat", cut);
  expect_error([&] { hbtrack::read_mat_variable_sparse(cut_path, "K"); }, cut_path,
               "corrupt MAT file: the sparse matrix at byte 128 ends before its values (the format stores array flags, dimensions, name, "
               "row indices, column starts and values)");
}

TEST_F(MatFileTest, TruncatedFileNeverCrashes) {
  const std::string path = path_for("full.mat");
  {
    MatWriter writer(path);
    writer.dense("K", example_matrix());
    writer.sparse("S", sparse_from(example_matrix()));
  }
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string truncated_path = path_for("truncated.mat");
  for (std::size_t length = 0; length < bytes.size(); length += 7) {
    write_text("truncated.mat", bytes.substr(0, length));
    for (const char* name : {"K", "S"}) {
      try {
        hbtrack::read_mat_variable_sparse(truncated_path, name);
      } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()).rfind(truncated_path + ": ", 0), 0u) << error.what();
      }
    }
  }
}

}  // namespace

}  // namespace hbtrack_tests::file_mat_file
