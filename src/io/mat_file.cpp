#include "hbtrack/io/mat_file.hpp"

#include <matio.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "hbtrack/io/mat_header_check.hpp"
#include "matrix_file_limits.hpp"

namespace hbtrack {

using namespace matrix_file;

namespace {

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
    case MAT_C_EMPTY:
      return "empty";
    case MAT_C_CELL:
      return "cell";
    case MAT_C_STRUCT:
      return "struct";
    case MAT_C_OBJECT:
      return "object";
    case MAT_C_CHAR:
      return "char";
    case MAT_C_SPARSE:
      return "sparse";
    case MAT_C_DOUBLE:
      return "double";
    case MAT_C_SINGLE:
      return "single";
    case MAT_C_INT8:
      return "int8";
    case MAT_C_UINT8:
      return "uint8";
    case MAT_C_INT16:
      return "int16";
    case MAT_C_UINT16:
      return "uint16";
    case MAT_C_INT32:
      return "int32";
    case MAT_C_UINT32:
      return "uint32";
    case MAT_C_INT64:
      return "int64";
    case MAT_C_UINT64:
      return "uint64";
    case MAT_C_FUNCTION:
      return "function handle";
    case MAT_C_OPAQUE:
      return "opaque object";
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
    case MAT_T_DOUBLE:
      return {&load_as_double<double>, sizeof(double)};
    case MAT_T_SINGLE:
      return {&load_as_double<float>, sizeof(float)};
    case MAT_T_INT8:
      return {&load_as_double<std::int8_t>, sizeof(std::int8_t)};
    case MAT_T_UINT8:
      return {&load_as_double<std::uint8_t>, sizeof(std::uint8_t)};
    case MAT_T_INT16:
      return {&load_as_double<std::int16_t>, sizeof(std::int16_t)};
    case MAT_T_UINT16:
      return {&load_as_double<std::uint16_t>, sizeof(std::uint16_t)};
    case MAT_T_INT32:
      return {&load_as_double<std::int32_t>, sizeof(std::int32_t)};
    case MAT_T_UINT32:
      return {&load_as_double<std::uint32_t>, sizeof(std::uint32_t)};
    case MAT_T_INT64:
      return {&load_as_double<std::int64_t>, sizeof(std::int64_t)};
    case MAT_T_UINT64:
      return {&load_as_double<std::uint64_t>, sizeof(std::uint64_t)};
    default:
      return {};
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
        variable->class_type == MAT_C_SPARSE ? sparse_triplets(*variable, rows, cols) : dense_triplets(*variable, rows, cols);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    return matrix;
  }

 private:
  [[noreturn]] void fail_variable(const std::string& what) const { fail(path_, "variable " + single_quoted(name_) + ": " + what); }

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
    if (info.class_type == MAT_C_SPARSE) return;               // its size depends on nnz, which the header lacks
    const std::size_t elements = info.dims[0] * info.dims[1];  // both at most kMaxDimension
    if (elements > static_cast<std::size_t>(kMaxEntries))
      fail_variable("has " + std::to_string(elements) + " elements, more than the limit of " + std::to_string(kMaxEntries));
    // v4/v5 store every element in at least one byte, and zlib expands at most ~1032:1.
    // v7.3 (HDF5) may legitimately store unwritten data as a fill value, so it is not bounded.
    if (version == MAT_FT_MAT73) return;
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path_, ec);
    if (ec) return;
    constexpr std::uintmax_t kMaxZlibRatio = 1032;
    const std::uintmax_t max_elements = info.compression == MAT_COMPRESSION_ZLIB ? file_bytes * kMaxZlibRatio : file_bytes;
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
      fail_variable("corrupt sparse column pointers (expected " + std::to_string(cols + 1) + ", found " + std::to_string(sparse->njc) +
                    ")");
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
        if (row >= rows) fail_variable("corrupt sparse row index " + std::to_string(row) + " in column " + std::to_string(col + 1));
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

}  // namespace

Eigen::SparseMatrix<double> read_mat_variable_sparse(const std::string& path, const std::string& name) {
  return MatVariableReader(path, name).read();
}

Eigen::MatrixXd read_mat_variable(const std::string& path, const std::string& name) {
  return to_dense(path + ": variable " + single_quoted(name), read_mat_variable_sparse(path, name));
}

}  // namespace hbtrack
