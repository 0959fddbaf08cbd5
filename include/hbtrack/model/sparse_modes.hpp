#pragma once
// The lowest undamped modes of a large sparse model, K phi = w^2 M phi, by a shift-invert Lanczos
// iteration (Spectra) on one sparse LDL^T factorisation of K - sigma M.
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "hbtrack/model/damping.hpp"

namespace hbtrack {

// The `count` lowest modes (frequencies in rad/s, increasing; shapes n x count, mass-normalised).
// `shift` (in rad^2/s^2) must lie below the lowest eigenvalue for K - shift M to be positive
// definite; 0 suits any model whose constraints remove the rigid-body motion. Small models are
// solved densely. Throws std::runtime_error when the factorisation or the iteration fails.
NormalModes lowest_sparse_modes(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass, int count,
                                double shift = 0.0);

using SparseLdlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
// The same at shift 0 with a factorisation of K the caller already holds (one LDL^T fewer).
NormalModes lowest_sparse_modes(const SparseLdlt& stiffness_factor, const Eigen::SparseMatrix<double>& stiffness,
                                const Eigen::SparseMatrix<double>& mass, int count);

}  // namespace hbtrack
