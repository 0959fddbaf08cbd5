#include "hbtrack/util/single_precision_lu.hpp"

#include <stdexcept>
#include <string>

#ifdef HBTRACK_OPENBLAS
extern "C" {
// LAPACK's Fortran interface as OpenBLAS exports it (column-major, 1-based pivots).
void sgetrf_(const int* m, const int* n, float* a, const int* lda, int* ipiv, int* info);
void sgetrs_(const char* trans, const int* n, const int* nrhs, const float* a, const int* lda, const int* ipiv, float* b, const int* ldb,
             int* info);
}
#endif

#include "openblas_lock.hpp"

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace hbtrack {

namespace {
// A scaled Jacobian's entries span more than single precision's normal range (the blade's: the
// elimination made subnormal floats), and x86 computes on subnormals about 100x slower:
// sgetrf took longer than dgetrf on the blade. Flushing them to zero while the single-precision
// kernels run (this thread's MXCSR, restored after) only changes factors that are approximate
// anyway.
class FlushSubnormals {
 public:
#if defined(__SSE__)
  FlushSubnormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }  // FTZ | DAZ
  ~FlushSubnormals() { _mm_setcsr(saved_); }

 private:
  unsigned int saved_;
#endif
};
}  // namespace

void SinglePrecisionLU::compute(const Eigen::MatrixXd& a) {
  if (a.rows() != a.cols()) throw std::invalid_argument("SinglePrecisionLU: the matrix is not square");
  const FlushSubnormals flush;
  factors_ = a.cast<float>();  // no allocation when the size is that of the previous factorization
  const int n = static_cast<int>(a.rows());
#ifdef HBTRACK_OPENBLAS
  use_one_openblas_thread();
  pivots_.resize(static_cast<size_t>(n));
  int info = 0;
  if (n > 0) {
    const std::lock_guard<std::mutex> lock(openblas_mutex());
    sgetrf_(&n, &n, factors_.data(), &n, pivots_.data(), &info);
  }
  if (info < 0) throw std::logic_error("SinglePrecisionLU: sgetrf rejected argument " + std::to_string(-info));
#else
  const Eigen::PartialPivLU<Eigen::Ref<Eigen::MatrixXf> > lu(factors_);  // factors in place
  permutation_ = lu.permutationP();
  (void)n;
#endif
}

bool SinglePrecisionLU::solve_in_place(Eigen::VectorXd& b) const {
  const FlushSubnormals flush;
  work_ = b.cast<float>();
#ifdef HBTRACK_OPENBLAS
  const int n = static_cast<int>(factors_.rows()), columns = 1;
  int info = 0;
  if (n > 0) {
    const std::lock_guard<std::mutex> lock(openblas_mutex());
    const char trans = 'N';
    sgetrs_(&trans, &n, &columns, factors_.data(), &n, pivots_.data(), work_.data(), &n, &info);
  }
  if (info < 0) throw std::logic_error("SinglePrecisionLU: sgetrs rejected argument " + std::to_string(-info));
#else
  work_ = permutation_ * work_;
  factors_.triangularView<Eigen::UnitLower>().solveInPlace(work_);
  factors_.triangularView<Eigen::Upper>().solveInPlace(work_);
#endif
  if (!work_.allFinite()) return false;
  b = work_.cast<double>();
  return true;
}

}  // namespace hbtrack
