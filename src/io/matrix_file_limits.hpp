#pragma once
// What the Matrix Market and .mat readers share: the sizes a corrupt or hostile header may not
// demand, and their one-line "<path>: <what is wrong>" failures (std::runtime_error).
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

namespace hbtrack::matrix_file {

// Building an Eigen sparse matrix allocates (and zeroes) an index per row and per column, so a
// corrupt size field could demand gigabytes without a single entry behind it, and seconds of
// zeroing (fuzzing: a .mat header of 1e8 columns took over 30 s under the sanitizers). 5e6 is
// far above any model hbtrack solves and keeps dimensions well inside Eigen's int storage index.
constexpr std::int64_t kMaxDimension = 5'000'000;
static_assert(kMaxDimension < std::numeric_limits<int>::max());
// A corrupt or hostile header must not be able to request an absurd allocation.
constexpr std::int64_t kMaxEntries = 1'000'000'000;
// The dense readers' copy of a sparse matrix: at most 4000 x 4000 entries (128 MB), the largest
// model a case file accepts (kMaxModelDofs); larger matrices are read sparse. kMaxEntries (8 GB
// dense) let a 106-byte sparse .mat record of one entry allocate 5.6 GB, and 1e8 (800 MB) still
// let such records take 1.7 GB of RSS under the fuzzer (issue 39).
constexpr std::int64_t kMaxDenseEntries = 16'000'000;
// Reserve at most this up front; the vector grows only as real entries arrive.
constexpr std::size_t kMaxReserve = std::size_t{1} << 20;

using Triplet = Eigen::Triplet<double>;

[[noreturn]] void fail(const std::string& path, const std::string& what);
std::string errno_text(int error_number);
// Text from the file goes into error messages; keep those one short printable line.
std::string printable(std::string_view text);
std::string single_quoted(std::string_view text);
// A missing file or a directory would otherwise surface as a confusing parse error.
void require_readable_file(const std::string& path);
// A handful of entries can describe a matrix far too big to hold densely; refuse rather than
// let the dense copy exhaust memory. `where` is the message prefix (path, plus variable for .mat).
Eigen::MatrixXd to_dense(const std::string& where, const Eigen::SparseMatrix<double>& sparse);

}  // namespace hbtrack::matrix_file
