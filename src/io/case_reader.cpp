#include "case_reader.hpp"

#include "hbtrack/io/mat_file.hpp"
#include "hbtrack/io/matrix_market.hpp"
#include "matrix_file_limits.hpp"

namespace hbtrack {

namespace fs = std::filesystem;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best_d <= std::max<size_t>(2, word.size() / 3) ? best : "";
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

MatrixXd CaseReader::matrix(const toml::value& v, const std::string& field, int n) const {
  MatrixXd m;
  const auto require_size = [&](Eigen::Index rows, Eigen::Index cols) {
    if (n >= 0 && (rows != n || cols != n))
      fail(&v, field,
           "expected " + std::to_string(n) + "x" + std::to_string(n) + " (one row per dof), got " + std::to_string(rows) + "x" +
               std::to_string(cols));
  };
  if (v.is_array()) {
    const auto& rows = v.as_array();
    if (rows.empty()) fail(&v, field, "empty matrix");
    for (size_t i = 0; i < rows.size(); ++i) {
      const VectorXd row = vector(rows[i], field + "[" + std::to_string(i) + "]");
      if (i == 0) m.resize(static_cast<Eigen::Index>(rows.size()), row.size());
      if (row.size() != m.cols())
        fail(&rows[i], field,
             "row " + std::to_string(i) + " has " + std::to_string(row.size()) + " entries, row 0 has " + std::to_string(m.cols()));
      m.row(static_cast<Eigen::Index>(i)) = row.transpose();
    }
  } else if (v.is_table()) {
    check_keys(v, field, {"file", "variable", "diagonal"});
    if (const toml::value* d = find(v, "diagonal")) {
      m = vector(*d, field + ".diagonal").asDiagonal();
    } else if (const toml::value* f = find(v, "file")) {
      const fs::path path = resolve(string(*f, field + ".file"));
      if (!fs::exists(path)) fail(f, field + ".file", "file '" + path.string() + "' does not exist");
      // A directory, a device (/dev/zero never ends) or a pipe is not a matrix file.
      if (!fs::is_regular_file(path)) fail(f, field + ".file", "'" + path.string() + "' is not a regular file");
      // Read sparse and sized against the dofs before the dense copy: a 30000 x 30000 file of one
      // entry made a 7.2 GB matrix before its size was refused.
      Eigen::SparseMatrix<double> sparse;
      try {
        if (path.extension() == ".mat") {
          const toml::value* var = find(v, "variable");
          if (!var) fail(&v, field + ".variable", "missing (required for a .mat file)");
          sparse = read_mat_variable_sparse(path.string(), string(*var, field + ".variable"));
        } else {
          sparse = read_matrix_market_sparse(path.string());
        }
      } catch (const std::runtime_error& e) {
        fail(f, field + ".file", e.what());
      }
      require_size(sparse.rows(), sparse.cols());
      try {
        m = matrix_file::to_dense(path.string(), sparse);
      } catch (const std::runtime_error& e) {
        fail(f, field + ".file", e.what());
      }
    } else {
      fail(&v, field, "a matrix table needs 'file' or 'diagonal'");
    }
  } else {
    fail(&v, field, "expected an array of rows or a table {file = ...} / {diagonal = [...]}");
  }
  require_size(m.rows(), m.cols());
  if (!m.allFinite()) fail(&v, field, "contains NaN or Inf");
  return m;
}

int dof_index(const CaseReader& in, const StructuralModel& m, const toml::value& v, const std::string& field) {
  const std::string name = in.string(v, field);
  const int i = m.find_dof(name);
  if (i < 0) {
    const std::string guess = nearest(name, m.dof_names);
    in.fail(&v, field, "unknown dof '" + name + "'" + (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
  }
  return i;
}

ParameterBinding binding(const CaseReader& in, const CaseDefinition& c, const toml::value& v, const std::string& field) {
  auto linked = [&](const toml::value& name_value, double scale, double offset) {
    const std::string name = in.string(name_value, field);
    const int index = c.parameters.find(name);
    if (index < 0) {
      const std::string guess = nearest(name, c.parameters.names());
      in.fail(&name_value, field,
              "unknown parameter '" + name + "'" + (guess.empty() ? " (declare it in [parameters])" : " (did you mean '" + guess + "'?)"));
    }
    return ParameterBinding::linked(index, scale, offset);
  };
  if (v.is_string()) return linked(v, 1.0, 0.0);
  if (v.is_table()) {
    in.check_keys(v, field, {"parameter", "scale", "offset"});
    return linked(in.require(v, "parameter", field + ".parameter"), in.number_or(v, "scale", field + ".scale", 1.0),
                  in.number_or(v, "offset", field + ".offset", 0.0));
  }
  return ParameterBinding::constant(in.number(v, field));
}

}  // namespace hbtrack
