#include "hill_pencil.hpp"

#include <algorithm>

namespace hbtrack {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Entries of the pencil J + s D1 + s^2 (I x M), gathered without forming it.
struct Pencil {
  const MatrixXd& j;
  const MatrixXd& d1;
  const MatrixXd& m;
  double s;
  double operator()(Index row, Index col) const {
    const Index n = m.rows();
    const double mass = row / n == col / n ? m(row % n, col % n) : 0.0;
    return j(row, col) + s * d1(row, col) + s * s * mass;
  }
  MatrixXd gather(const std::vector<Index>& rows, const std::vector<Index>& cols) const {
    MatrixXd out(static_cast<Index>(rows.size()), static_cast<Index>(cols.size()));
    for (size_t c = 0; c < cols.size(); ++c)
      for (size_t r = 0; r < rows.size(); ++r) out(static_cast<Index>(r), static_cast<Index>(c)) = (*this)(rows[r], cols[c]);
    return out;
  }
};

VectorXd gather(const VectorXd& v, const std::vector<Index>& at) {
  VectorXd out(static_cast<Index>(at.size()));
  for (size_t i = 0; i < at.size(); ++i) out(static_cast<Index>(i)) = v(at[i]);
  return out;
}

}  // namespace

HillPencil::HillPencil(const MatrixXd& jacobian, const MatrixXd& damping, const MatrixXd& mass, double shift,
                       const std::vector<int>& coupled)
    : size_(jacobian.rows()) {
  const Pencil pencil{jacobian, damping, mass, shift};
  const int n = static_cast<int>(mass.rows());
  const int blocks = static_cast<int>(size_ / n);
  std::vector<char> is_coupled(static_cast<size_t>(n), 0);
  for (int d : coupled) is_coupled[static_cast<size_t>(d)] = 1;
  // Harmonic 0 is block 0; harmonic j the blocks 2j-1 (cosine) and 2j (sine).
  for (int first = 0; first < blocks; first = first == 0 ? 1 : first + 2) {
    Group g;
    for (int b = first; b < std::min(blocks, first == 0 ? 1 : first + 2); ++b)
      for (int d = 0; d < n; ++d) {
        const Index at = static_cast<Index>(b) * n + d;
        if (is_coupled[static_cast<size_t>(d)]) {
          g.coupled_in_schur.push_back(static_cast<Index>(schur_positions_.size()));
          g.coupled.push_back(at);
          schur_positions_.push_back(at);
        } else {
          g.linear.push_back(at);
        }
      }
    groups_.push_back(std::move(g));
  }
  MatrixXd schur = pencil.gather(schur_positions_, schur_positions_);
  for (Group& g : groups_) {
    if (g.linear.empty()) continue;
    g.lu.compute(pencil.gather(g.linear, g.linear));
    g.to_linear = pencil.gather(g.linear, g.coupled);
    g.from_linear = pencil.gather(g.coupled, g.linear);
    // Only this harmonic's coupled dofs see its linear dofs.
    const MatrixXd correction = g.from_linear * g.lu.solve(g.to_linear);
    for (size_t j = 0; j < g.coupled.size(); ++j)
      for (size_t i = 0; i < g.coupled.size(); ++i)
        schur(g.coupled_in_schur[i], g.coupled_in_schur[j]) -= correction(static_cast<Index>(i), static_cast<Index>(j));
  }
  schur_.compute(schur);
}

VectorXd HillPencil::solve(const VectorXd& r) const {
  VectorXd rhs = gather(r, schur_positions_);
  std::vector<VectorXd> eliminated(groups_.size());
  for (size_t k = 0; k < groups_.size(); ++k) {
    const Group& g = groups_[k];
    if (g.linear.empty()) continue;
    eliminated[k] = g.lu.solve(gather(r, g.linear));
    const VectorXd push = g.from_linear * eliminated[k];
    for (size_t i = 0; i < g.coupled.size(); ++i) rhs(g.coupled_in_schur[i]) -= push(static_cast<Index>(i));
  }
  const VectorXd y_coupled = schur_.solve(rhs);
  VectorXd y(size_);
  for (size_t i = 0; i < schur_positions_.size(); ++i) y(schur_positions_[i]) = y_coupled(static_cast<Index>(i));
  for (const Group& g : groups_) {
    if (g.linear.empty()) continue;
    const VectorXd y_linear = g.lu.solve(gather(r, g.linear) - g.to_linear * gather(y_coupled, g.coupled_in_schur));
    for (size_t i = 0; i < g.linear.size(); ++i) y(g.linear[i]) = y_linear(static_cast<Index>(i));
  }
  return y;
}

}  // namespace hbtrack
