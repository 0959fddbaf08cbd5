#include "hbtrack/util/dense_product.hpp"

#include <stdexcept>

#ifdef HBTRACK_OPENBLAS
extern "C" {
// BLAS's Fortran interface as OpenBLAS exports it (column-major).
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* b, const int* ldb, const double* beta, double* c, const int* ldc);
}
#endif

#include "openblas_lock.hpp"

namespace hbtrack {

void multiply(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd& c) {
  if (a.cols() != b.rows()) throw std::invalid_argument("multiply: inner dimensions differ");
  c.resize(a.rows(), b.cols());
#ifdef HBTRACK_OPENBLAS
  use_one_openblas_thread();
  const int m = static_cast<int>(a.rows()), n = static_cast<int>(b.cols()), k = static_cast<int>(a.cols());
  if (m == 0 || n == 0) return;
  if (k == 0) {
    c.setZero();
    return;
  }
  const int lda = static_cast<int>(a.outerStride()), ldb = static_cast<int>(b.outerStride());
  const double one = 1.0, zero = 0.0;
  const std::lock_guard<std::mutex> lock(openblas_mutex());
  dgemm_("N", "N", &m, &n, &k, &one, a.data(), &lda, b.data(), &ldb, &zero, c.data(), &m);
#else
  c.noalias() = a * b;
#endif
}

}  // namespace hbtrack
