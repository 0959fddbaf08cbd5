#pragma once
// Readers for the matrix files users bring: Matrix Market (.mtx) and MATLAB .mat (libmatio).
// Every failure throws std::runtime_error with one line "<path>: <what is wrong>" (naming the
// variable for .mat files); nothing is returned half-read.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <string>

namespace hbtrack {

// Matrix Market: `matrix coordinate|array real|integer general|symmetric` (symmetric is
// expanded). Indices 1-based; duplicate coordinate entries are summed.
Eigen::SparseMatrix<double> read_matrix_market_sparse(const std::string& path);
Eigen::MatrixXd read_matrix_market(const std::string& path);
void write_matrix_market(const std::string& path, const Eigen::SparseMatrix<double>& matrix);

// A real double matrix (dense or sparse) stored as variable `name` in a .mat file (v5, v7, and
// v7.3 when libmatio was built with HDF5). Vectors come back as n x 1 or 1 x n.
Eigen::SparseMatrix<double> read_mat_variable_sparse(const std::string& path, const std::string& name);
Eigen::MatrixXd read_mat_variable(const std::string& path, const std::string& name);

}  // namespace hbtrack
