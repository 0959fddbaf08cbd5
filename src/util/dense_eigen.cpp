#include "hbtrack/util/dense_eigen.hpp"

#include <Eigen/Eigenvalues>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef HBTRACK_OPENBLAS
extern "C" {
// LAPACK's Fortran interface as OpenBLAS exports it (column-major).
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr, double* wi, double* vl,
            const int* ldvl, double* vr, const int* ldvr, double* work, const int* lwork, int* info);
}
#include "openblas_lock.hpp"
#endif

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXcd;

#ifdef HBTRACK_OPENBLAS
VectorXcd dense_eigenvalues(const MatrixXd& a, Eigen::MatrixXcd* vectors) {
  if (a.rows() != a.cols()) throw std::invalid_argument("dense_eigenvalues: the matrix is not square");
  const int n = static_cast<int>(a.rows());
  VectorXcd values(n);
  if (vectors) vectors->resize(n, n);
  if (n == 0) return values;
  MatrixXd work_matrix = a, right(vectors ? n : 1, vectors ? n : 1);
  std::vector<double> wr(static_cast<size_t>(n)), wi(static_cast<size_t>(n));
  const char no = 'N', job = vectors ? 'V' : 'N';
  const int one = 1, ldvr = vectors ? n : 1;
  int info = 0, query = -1;
  double optimal = 0, unused = 0;
  const std::lock_guard<std::mutex> lock(openblas_mutex());
  dgeev_(&no, &job, &n, work_matrix.data(), &n, wr.data(), wi.data(), &unused, &one, right.data(), &ldvr, &optimal, &query, &info);
  int lwork = std::max(static_cast<int>(optimal), 4 * n);
  std::vector<double> work(static_cast<size_t>(lwork));
  dgeev_(&no, &job, &n, work_matrix.data(), &n, wr.data(), wi.data(), &unused, &one, right.data(), &ldvr, work.data(), &lwork, &info);
  if (info < 0) throw std::logic_error("dense_eigenvalues: dgeev rejected argument " + std::to_string(-info));
  if (info > 0) throw std::runtime_error("dense_eigenvalues: the QR iteration did not converge");
  for (int j = 0; j < n; ++j) values(j) = {wr[static_cast<size_t>(j)], wi[static_cast<size_t>(j)]};
  if (vectors) {
    // A complex pair j, j + 1 (wi[j] > 0) is stored as the real and imaginary parts of the first.
    for (int j = 0; j < n; ++j) {
      if (wi[static_cast<size_t>(j)] > 0 && j + 1 < n) {
        vectors->col(j).real() = right.col(j);
        vectors->col(j).imag() = right.col(j + 1);
        vectors->col(j + 1) = vectors->col(j).conjugate();
        ++j;
      } else {
        vectors->col(j).real() = right.col(j);
        vectors->col(j).imag().setZero();
      }
    }
  }
  return values;
}
#else
VectorXcd dense_eigenvalues(const MatrixXd& a, Eigen::MatrixXcd* vectors) {
  if (a.rows() != a.cols()) throw std::invalid_argument("dense_eigenvalues: the matrix is not square");
  const Eigen::EigenSolver<MatrixXd> solver(a, vectors != nullptr);
  if (solver.info() != Eigen::Success) throw std::runtime_error("dense_eigenvalues: the QR iteration did not converge");
  if (vectors) *vectors = solver.eigenvectors();
  return solver.eigenvalues();
}
#endif

}  // namespace hbtrack
