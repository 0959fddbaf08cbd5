#pragma once
// MATLAB .mat files (libmatio), where many users hold their reduced models. Every failure throws
// std::runtime_error with one line "<path>: variable '<name>': <what is wrong>"; nothing is
// returned half-read.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <string>

namespace hbtrack {

// A real double matrix (dense or sparse) stored as variable `name` (v5, v7, and v7.3 when
// libmatio was built with HDF5). Vectors come back as n x 1 or 1 x n.
Eigen::SparseMatrix<double> read_mat_variable_sparse(const std::string& path, const std::string& name);
Eigen::MatrixXd read_mat_variable(const std::string& path, const std::string& name);

}  // namespace hbtrack
