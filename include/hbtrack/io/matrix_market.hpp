#pragma once
// Matrix Market files (.mtx), the sparse-matrix exchange format of finite-element tools. Every
// failure throws std::runtime_error with one line "<path>: <what is wrong>"; nothing is returned
// half-read.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <string>

namespace hbtrack {

// `matrix coordinate|array real|integer general|symmetric` (symmetric is expanded). Indices
// 1-based; duplicate coordinate entries are summed.
Eigen::SparseMatrix<double> read_matrix_market_sparse(const std::string& path);
Eigen::MatrixXd read_matrix_market(const std::string& path);
void write_matrix_market(const std::string& path, const Eigen::SparseMatrix<double>& matrix);

}  // namespace hbtrack
