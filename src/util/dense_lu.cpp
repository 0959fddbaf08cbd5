#include "hbtrack/util/dense_lu.hpp"

#include <cmath>
#include <stdexcept>

#ifdef HBTRACK_OPENBLAS
extern "C" {
// LAPACK's Fortran interface as OpenBLAS exports it (column-major, 1-based pivots).
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv, double* b, const int* ldb,
             int* info);
char* openblas_get_corename(void);
}
#endif

#include "openblas_lock.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

#ifdef HBTRACK_OPENBLAS
namespace {
// dgetrs: OpenBLAS's triangular solves have the processor's vector kernels, Eigen's (compiled
// for baseline x86-64) do not; the solves are most of a chord iteration and of Hill's Arnoldi.
void lapack_solve(char trans, const MatrixXd& factors, const std::vector<int>& pivots, VectorXd& b) {
  const int n = static_cast<int>(factors.rows()), columns = 1;
  int info = 0;
  if (n > 0) {
    const std::lock_guard<std::mutex> lock(openblas_mutex());
    dgetrs_(&trans, &n, &columns, factors.data(), &n, pivots.data(), b.data(), &n, &info);
  }
  if (info < 0) throw std::logic_error("DenseLU: dgetrs rejected argument " + std::to_string(-info));
}
}  // namespace
#endif

void DenseLU::compute(const MatrixXd& a) {
  if (a.rows() != a.cols()) throw std::invalid_argument("DenseLU: the matrix is not square");
  factors_ = a;  // no allocation when the size is that of the previous factorization
  const int n = static_cast<int>(a.rows());
#ifdef HBTRACK_OPENBLAS
  use_one_openblas_thread();
  pivots_.resize(static_cast<size_t>(n));
  int info = 0;
  if (n > 0) {
    const std::lock_guard<std::mutex> lock(openblas_mutex());
    dgetrf_(&n, &n, factors_.data(), &n, pivots_.data(), &info);
  }
  if (info < 0) throw std::logic_error("DenseLU: dgetrf rejected argument " + std::to_string(-info));
  // info > 0 is an exact zero pivot: the factors are still complete (determinant 0, solves inf).
  Eigen::Transpositions<Eigen::Dynamic, Eigen::Dynamic, int> swaps(n);
  for (int i = 0; i < n; ++i) swaps.indices()(i) = pivots_[static_cast<size_t>(i)] - 1;
  permutation_ = swaps;
#else
  const Eigen::PartialPivLU<Eigen::Ref<MatrixXd> > lu(factors_);  // factors in place
  permutation_ = lu.permutationP();
  (void)n;
#endif
}

void DenseLU::solve_in_place(VectorXd& b) const {
#ifdef HBTRACK_OPENBLAS
  lapack_solve('N', factors_, pivots_, b);
#else
  b = permutation_ * b;  // Eigen applies a permutation in place
  factors_.triangularView<Eigen::UnitLower>().solveInPlace(b);
  factors_.triangularView<Eigen::Upper>().solveInPlace(b);
#endif
}

void DenseLU::solve_transposed_in_place(VectorXd& b) const {
#ifdef HBTRACK_OPENBLAS
  lapack_solve('T', factors_, pivots_, b);
#else
  // A = P^T L U, so A^T = U^T L^T P.
  factors_.triangularView<Eigen::Upper>().transpose().solveInPlace(b);
  factors_.triangularView<Eigen::UnitLower>().transpose().solveInPlace(b);
  b = permutation_.transpose() * b;
#endif
}

VectorXd DenseLU::solve(const VectorXd& b) const {
  VectorXd x = b;
  solve_in_place(x);
  return x;
}

VectorXd DenseLU::solve_transposed(const VectorXd& b) const {
  VectorXd x = b;
  solve_transposed_in_place(x);
  return x;
}

double DenseLU::log_abs_determinant() const {
  double sum = 0;
  for (Eigen::Index i = 0; i < factors_.rows(); ++i) sum += std::log(std::abs(factors_(i, i)));
  return sum;
}

int DenseLU::determinant_sign() const {
  int sign = static_cast<int>(permutation_.determinant());
  for (Eigen::Index i = 0; i < factors_.rows(); ++i) {
    if (factors_(i, i) == 0.0) return 0;
    if (factors_(i, i) < 0) sign = -sign;
  }
  return sign;
}

bool refine_last_unit_solution(const DenseLU& nearby, const MatrixXd& a, VectorXd& x, VectorXd& residual, int max_steps) {
  const Eigen::Index n = a.rows();
  const double matrix_norm = a.cwiseAbs().rowwise().sum().maxCoeff();
  x.setZero(n);
  residual.setZero(n);
  residual(n - 1) = 1.0;
  for (int step = 0; step < max_steps; ++step) {
    nearby.solve_in_place(residual);
    x += residual;
    residual.noalias() = -a * x;
    residual(n - 1) += 1.0;
    if (!residual.allFinite()) return false;
    if (residual.lpNorm<Eigen::Infinity>() <= 1e-13 * matrix_norm * x.lpNorm<Eigen::Infinity>()) return true;
  }
  return false;
}

double estimate_norm1(Eigen::Index n, const std::function<void(VectorXd&)>& apply, const std::function<void(VectorXd&)>& apply_transposed) {
  if (n == 0) return 0.0;
  // Hager: maximise ||M x||_1 over the unit 1-norm ball by steepest ascent from the centre;
  // each step is one product with M and one with M^T, and it stops at a vertex.
  VectorXd x = VectorXd::Constant(n, 1.0 / static_cast<double>(n));
  double estimate = 0;
  Eigen::Index previous_vertex = -1;
  for (int step = 0; step < 5; ++step) {
    apply(x);
    estimate = std::max(estimate, x.lpNorm<1>());
    VectorXd z = x.unaryExpr([](double v) { return v >= 0 ? 1.0 : -1.0; });
    apply_transposed(z);
    Eigen::Index vertex = 0;
    z.cwiseAbs().maxCoeff(&vertex);
    if (vertex == previous_vertex) break;  // ascent returns to the vertex it came from
    previous_vertex = vertex;
    x.setZero();
    x(vertex) = 1.0;
  }
  // Higham's alternating vector catches matrices on which the ascent stalls early.
  VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i)
    b(i) = (i % 2 ? -1.0 : 1.0) * (1.0 + static_cast<double>(i) / static_cast<double>(std::max<Eigen::Index>(n - 1, 1)));
  apply(b);
  return std::max(estimate, 2.0 * b.lpNorm<1>() / (3.0 * static_cast<double>(n)));
}

std::string DenseLU::backend() {
#ifdef HBTRACK_OPENBLAS
  return std::string("OpenBLAS (") + openblas_get_corename() + ")";
#else
  return "Eigen";
#endif
}

}  // namespace hbtrack
