#include "hbtrack/io/matrix_market.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

#include "matrix_file_test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_matrix_market {

namespace {

using namespace hbtrack::test;  // TempDirTest, expect_error, example_matrix, sparse_from, fs

// ---------------------------------------------------------------------------------------------
// Matrix Market: valid files

using MatrixMarketTest = TempDirTest;

TEST_F(MatrixMarketTest, ReadsCoordinateGeneral) {
  const std::string path = write_text("general.mtx",
                                      "%%MatrixMarket matrix coordinate real general\n"
                                      "% a comment\n"
                                      "3 4 6\n"
                                      "1 1 4.0\n"
                                      "2 2 2.25\n"
                                      "3 1 7\n"
                                      "1 3 -1.5\n"
                                      "2 4 1e-12\n"
                                      "3 4 -3.0E0\n");
  const Eigen::SparseMatrix<double> sparse = hbtrack::read_matrix_market_sparse(path);
  EXPECT_EQ(sparse.rows(), 3);
  EXPECT_EQ(sparse.cols(), 4);
  EXPECT_EQ(sparse.nonZeros(), 6);
  EXPECT_EQ(Eigen::MatrixXd(sparse), example_matrix());
  EXPECT_EQ(hbtrack::read_matrix_market(path), example_matrix());
}

TEST_F(MatrixMarketTest, ExpandsCoordinateSymmetric) {
  const std::string path = write_text("symmetric.mtx",
                                      "%%MatrixMarket matrix coordinate real symmetric\n"
                                      "3 3 4\n"
                                      "1 1 2\n"
                                      "2 1 -1\n"
                                      "3 2 -1\n"
                                      "3 3 2\n");
  Eigen::MatrixXd expected(3, 3);
  expected << 2, -1, 0, -1, 0, -1, 0, -1, 2;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ExpandsSymmetricGivenAsUpperTriangle) {
  const std::string path = write_text("upper.mtx",
                                      "%%MatrixMarket matrix coordinate real symmetric\n"
                                      "2 2 2\n"
                                      "1 2 5\n"
                                      "2 2 1\n");
  Eigen::MatrixXd expected(2, 2);
  expected << 0, 5, 5, 1;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ExpandsSkewSymmetric) {
  const std::string path = write_text("skew.mtx",
                                      "%%MatrixMarket matrix coordinate real skew-symmetric\n"
                                      "3 3 2\n"
                                      "2 1 1.5\n"
                                      "3 1 -2\n");
  Eigen::MatrixXd expected(3, 3);
  expected << 0, -1.5, 2, 1.5, 0, 0, -2, 0, 0;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ReadsArrayInColumnMajorOrder) {
  const std::string path = write_text("array.mtx",
                                      "%%MatrixMarket matrix array real general\n"
                                      "% column by column, as the standard says\n"
                                      "2 3\n"
                                      "1\n2\n3\n4\n5\n6\n");
  Eigen::MatrixXd expected(2, 3);
  expected << 1, 3, 5, 2, 4, 6;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ReadsArraySymmetricLowerTriangle) {
  const std::string path = write_text("array_symmetric.mtx",
                                      "%%MatrixMarket matrix array real symmetric\n"
                                      "3 3\n"
                                      "1\n2\n3\n4\n5\n6\n");
  Eigen::MatrixXd expected(3, 3);
  expected << 1, 2, 3, 2, 4, 5, 3, 5, 6;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ReadsIntegerField) {
  const std::string path = write_text("integer.mtx",
                                      "%%MatrixMarket matrix coordinate integer general\n"
                                      "2 2 3\n"
                                      "1 1 7\n"
                                      "2 1 -3\n"
                                      "2 2 +12\n");
  Eigen::MatrixXd expected(2, 2);
  expected << 7, 0, -3, 12;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ReadsPatternFieldAsOnes) {
  const std::string path = write_text("pattern.mtx",
                                      "%%MatrixMarket matrix coordinate pattern general\n"
                                      "2 2 2\n"
                                      "1 2\n"
                                      "2 1\n");
  Eigen::MatrixXd expected(2, 2);
  expected << 0, 1, 1, 0;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, SumsDuplicateEntries) {
  const std::string path = write_text("duplicates.mtx",
                                      "%%MatrixMarket matrix coordinate real general\n"
                                      "2 2 4\n"
                                      "1 1 1.5\n"
                                      "2 2 1\n"
                                      "1 1 2.5\n"
                                      "1 1 -1\n");
  const Eigen::SparseMatrix<double> sparse = hbtrack::read_matrix_market_sparse(path);
  EXPECT_EQ(sparse.nonZeros(), 2);
  EXPECT_EQ(sparse.coeff(0, 0), 3.0);
  EXPECT_EQ(sparse.coeff(1, 1), 1.0);
}

TEST_F(MatrixMarketTest, ToleratesCrlfTabsBlankLinesAndCaseInBanner) {
  const std::string path = write_text("windows.mtx",
                                      "%%MatrixMarket MATRIX Coordinate REAL General\r\n"
                                      "\r\n"
                                      "  2\t2  1 \r\n"
                                      "%comment between entries\r\n"
                                      "\t2 1\t-4.5\r\n"
                                      "\r\n");
  Eigen::MatrixXd expected(2, 2);
  expected << 0, 0, -4.5, 0;
  EXPECT_EQ(hbtrack::read_matrix_market(path), expected);
}

TEST_F(MatrixMarketTest, ReadsEmptyMatrix) {
  const std::string path = write_text("empty.mtx", "%%MatrixMarket matrix coordinate real general\n4 5 0\n");
  const Eigen::SparseMatrix<double> sparse = hbtrack::read_matrix_market_sparse(path);
  EXPECT_EQ(sparse.rows(), 4);
  EXPECT_EQ(sparse.cols(), 5);
  EXPECT_EQ(sparse.nonZeros(), 0);
}

TEST_F(MatrixMarketTest, DenseReaderRefusesHugeMatrix) {
  const std::string path = write_text("huge.mtx", "%%MatrixMarket matrix coordinate real general\n100000 100000 1\n5 7 1.0\n");
  EXPECT_EQ(hbtrack::read_matrix_market_sparse(path).nonZeros(), 1);
  expect_error([&] { hbtrack::read_matrix_market(path); }, path, "too large to read as a dense matrix");
}

// Issue 39's fuzzing: the dense copy's limit was 1e9 entries (8 GB); it is now 4000 x 4000 (128
// MB, the largest model a case accepts), so a one-entry file of 4001 x 4000 is refused dense,
// read sparse.
TEST_F(MatrixMarketTest, DenseReaderStopsAt4000By4000Entries) {
  const std::string path = write_text("wide.mtx", "%%MatrixMarket matrix coordinate real general\n4001 4000 1\n5 7 1.0\n");
  EXPECT_EQ(hbtrack::read_matrix_market_sparse(path).nonZeros(), 1);
  expect_error([&] { hbtrack::read_matrix_market(path); }, path,
               "4001 x 4000 is too large to read as a dense matrix (limit 16000000 entries, 128 MB); use the sparse reader");
}

TEST_F(MatrixMarketTest, UnderflowingValueReadsAsZero) {
  const std::string path = write_text("tiny.mtx", "%%MatrixMarket matrix coordinate real general\n1 2 2\n1 1 1e-400\n1 2 4.9e-324\n");
  const Eigen::MatrixXd matrix = hbtrack::read_matrix_market(path);
  EXPECT_EQ(matrix(0, 0), 0.0);
  EXPECT_GT(matrix(0, 1), 0.0);
}

TEST_F(MatrixMarketTest, RoundTripIsBitExact) {
  Eigen::MatrixXd dense(3, 3);
  dense << 1.0 / 3.0, 0.0, -2.0 / 7.0,  //
      1e-300, 6.02214076e23, 0.0,       //
      0.0, -0.1, 5e-324;
  const Eigen::SparseMatrix<double> original = sparse_from(dense);
  const std::string path = path_for("round_trip.mtx");
  hbtrack::write_matrix_market(path, original);
  const Eigen::SparseMatrix<double> read_back = hbtrack::read_matrix_market_sparse(path);
  EXPECT_EQ(read_back.rows(), original.rows());
  EXPECT_EQ(read_back.cols(), original.cols());
  EXPECT_EQ(read_back.nonZeros(), original.nonZeros());
  EXPECT_EQ(Eigen::MatrixXd(read_back), dense);  // exact: %.17g round-trips every double
}

TEST_F(MatrixMarketTest, WriteRefusesNonFiniteValue) {
  Eigen::SparseMatrix<double> matrix(2, 2);
  matrix.insert(1, 0) = std::numeric_limits<double>::quiet_NaN();
  const std::string path = path_for("nan.mtx");
  expect_error([&] { hbtrack::write_matrix_market(path, matrix); }, path, "non-finite");
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(MatrixMarketTest, WriteReportsUnwritablePath) {
  const std::string path = path_for("no_such_dir/out.mtx");
  expect_error([&] { hbtrack::write_matrix_market(path, Eigen::SparseMatrix<double>(1, 1)); }, path, "cannot open for writing");
}

// ---------------------------------------------------------------------------------------------
// Matrix Market: malformed files

struct MalformedCase {
  const char* name;
  const char* content;
  const char* phrase;
};

class MalformedMatrixMarketTest : public TempDirTest, public ::testing::WithParamInterface<MalformedCase> {};

TEST_P(MalformedMatrixMarketTest, ThrowsWithPathAndReason) {
  const std::string path = write_text("bad.mtx", GetParam().content);
  expect_error([&] { hbtrack::read_matrix_market_sparse(path); }, path, GetParam().phrase);
  expect_error([&] { hbtrack::read_matrix_market(path); }, path, GetParam().phrase);
}

constexpr const char* kCoordinateBanner = "%%MatrixMarket matrix coordinate real general\n";

const MalformedCase kMalformedCases[] = {
    {"EmptyFile", "", "missing '%%MatrixMarket' banner"},
    {"MissingBanner", "3 3 1\n1 1 1.0\n", "line 1: missing '%%MatrixMarket' banner"},
    {"BannerTooShort", "%%MatrixMarket matrix coordinate real\n1 1 0\n", "line 1: banner must be"},
    {"UnknownObject", "%%MatrixMarket vector coordinate real general\n1 1 0\n", "unsupported object 'vector'"},
    {"UnknownFormat", "%%MatrixMarket matrix dense real general\n1 1 0\n", "unknown format 'dense'"},
    {"BadField", "%%MatrixMarket matrix coordinate reel general\n1 1 0\n", "unknown field 'reel'"},
    {"ComplexField", "%%MatrixMarket matrix coordinate complex general\n1 1 0\n", "complex matrices are not supported"},
    {"Hermitian", "%%MatrixMarket matrix coordinate real hermitian\n1 1 0\n", "hermitian matrices are not supported"},
    {"UnknownSymmetry", "%%MatrixMarket matrix coordinate real diagonal\n1 1 0\n", "unknown symmetry 'diagonal'"},
    {"PatternArray", "%%MatrixMarket matrix array pattern general\n1 1\n", "pattern field is only valid"},
    {"MissingSizeLine", "%%MatrixMarket matrix coordinate real general\n% only comments\n", "missing size line"},
    {"TruncatedSizeLine", "%%MatrixMarket matrix coordinate real general\n3 3\n1 1 1\n",
     "line 2: size line must be 'rows columns entries' (3 integers), found 2"},
    {"ArraySizeLineWithThreeNumbers", "%%MatrixMarket matrix array real general\n2 2 4\n1\n2\n3\n4\n",
     "line 2: size line must be 'rows columns' (2 integers)"},
    {"NegativeSize", "%%MatrixMarket matrix coordinate real general\n-3 3 1\n1 1 1\n", "'-3' is not a non-negative integer"},
    {"NonIntegerSize", "%%MatrixMarket matrix coordinate real general\n3.5 3 1\n1 1 1\n", "'3.5' is not a non-negative integer"},
    {"DimensionTooLarge", "%%MatrixMarket matrix coordinate real general\n3000000000 3 0\n", "exceeds the limit"},
    {"TooManyDeclaredEntries", "%%MatrixMarket matrix coordinate real general\n10 10 1000000001\n1 1 1\n",
     "entries 1000000001 exceeds the limit of 1000000000"},
    {"ArrayTooLarge", "%%MatrixMarket matrix array real general\n100000 100000\n1\n", "exceeds the limit"},
    {"SymmetricNotSquare", "%%MatrixMarket matrix coordinate real symmetric\n2 3 1\n1 1 1\n", "must be square"},
    {"RowOutOfRange", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n4 1 2\n", "line 4: row index 4 out of range 1..3"},
    {"ColumnZero", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1 0 1\n", "line 3: column index 0 out of range 1..3"},
    {"IndexNotInteger", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1.0 1 1\n", "row index '1.0' is not an integer"},
    {"TooFewEntries", "%%MatrixMarket matrix coordinate real general\n3 3 3\n1 1 1\n2 2 2\n", "file ends after 2 of 3 entries"},
    {"TooFewArrayEntries", "%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n", "file ends after 3 of 4"},
    {"TooManyEntries", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1 1 1\n2 2 2\n",
     "line 4: more entries than the size line declares"},
    {"EntryMissingValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1 1\n",
     "line 3: expected 3 numbers (row column value), found 2"},
    {"EntryWithExtraNumber", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1 1 1 1\n", "line 3: expected 3 numbers"},
    {"NonNumericValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1 1 abc\n", "line 3: value 'abc' is not a number"},
    {"TrailingGarbageInValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n1 1 1.5x\n", "value '1.5x' is not a number"},
    {"NaNValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n2 2 nan\n", "line 3: value 'nan' is not finite"},
    {"InfValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n2 2 -inf\n", "value '-inf' is not finite"},
    {"OverflowingValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n2 2 1e999\n", "out of range"},
    {"FractionInIntegerField", "%%MatrixMarket matrix coordinate integer general\n3 3 1\n2 2 1.5\n", "value '1.5' is not an integer"},
    {"BinaryGarbageValue", "%%MatrixMarket matrix coordinate real general\n3 3 1\n2 2 \x01\x7f\xff\n", "value '?\?\?' is not a number"},
    {"SymmetricBothTriangles", "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n2 1 1\n1 2 1\n", "both triangles"},
    {"SkewSymmetricDiagonal", "%%MatrixMarket matrix coordinate real skew-symmetric\n2 2 1\n1 1 3\n", "nonzero diagonal"},
};

INSTANTIATE_TEST_SUITE_P(MatrixMarket, MalformedMatrixMarketTest, ::testing::ValuesIn(kMalformedCases),
                         [](const ::testing::TestParamInfo<MalformedCase>& case_info) { return case_info.param.name; });

TEST_F(MatrixMarketTest, MissingFileIsReported) {
  const std::string path = path_for("does_not_exist.mtx");
  expect_error([&] { hbtrack::read_matrix_market(path); }, path, "cannot open file");
}

TEST_F(MatrixMarketTest, DirectoryIsReported) {
  const std::string path = dir_.string();
  expect_error([&] { hbtrack::read_matrix_market(path); }, path, "is a directory");
}

// A cheap stand-in for the later fuzzing: every prefix and many single-byte corruptions of a
// valid file must either parse or throw std::runtime_error (the sanitizers catch the rest).
TEST_F(MatrixMarketTest, TruncatedOrCorruptedInputNeverCrashes) {
  const std::string valid = std::string(kCoordinateBanner) + "% c\n3 3 4\n1 1 1.5\n3 2 -2e3\n2 2 7\n3 3 1\n";
  const std::string path = path_for("fuzz.mtx");
  const auto parse_or_runtime_error = [&](const std::string& content) {
    write_text("fuzz.mtx", content);
    try {
      hbtrack::read_matrix_market_sparse(path);
    } catch (const std::runtime_error&) {
    }
  };
  for (std::size_t length = 0; length <= valid.size(); ++length) parse_or_runtime_error(valid.substr(0, length));
  const std::string replacements("\0 \n%-+.e9x", 11);
  for (std::size_t position = 0; position < valid.size(); ++position)
    for (const char replacement : replacements) {
      std::string corrupted = valid;
      corrupted[position] = replacement;
      EXPECT_NO_FATAL_FAILURE(parse_or_runtime_error(corrupted));
    }
}
}  // namespace

}  // namespace hbtrack_tests::file_matrix_market
