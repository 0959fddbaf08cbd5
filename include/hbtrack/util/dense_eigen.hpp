#pragma once
// Eigenvalues (and optionally right eigenvectors) of a dense real square matrix: Hill's matrix
// on small systems, the monodromy matrix. Backed by LAPACK's dgeev from OpenBLAS when the build
// found it (HBTRACK_OPENBLAS: blocked Hessenberg QR with the processor's kernels), otherwise by
// Eigen's EigenSolver. Eigenvectors are columns of unit Euclidean norm; their phase is the
// backend's.
#include <Eigen/Dense>

namespace hbtrack {

// Throws std::runtime_error when the QR iteration fails to converge.
Eigen::VectorXcd dense_eigenvalues(const Eigen::MatrixXd& a, Eigen::MatrixXcd* vectors = nullptr);

}  // namespace hbtrack
