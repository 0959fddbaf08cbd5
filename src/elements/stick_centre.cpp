#include "stick_centre.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

StickCentre one_direction(const MatrixXd& x, const VectorXd& r) {
  // The sticking positions form [max (x - r), min (x + r)]: its middle.
  Eigen::Index a = 0, b = 0;
  const double low = (x.col(0) - r).maxCoeff(&a), high = (x.col(0) + r).minCoeff(&b);
  StickCentre c;
  c.z = VectorXd::Constant(1, 0.5 * (low + high));
  c.margin = 0.5 * (high - low);
  c.support = {a, b};
  c.dz_dx = {MatrixXd::Constant(1, 1, 0.5), MatrixXd::Constant(1, 1, 0.5)};
  c.dz_dr = {VectorXd::Constant(1, -0.5), VectorXd::Constant(1, 0.5)};
  return c;
}

// Weighted points (x_i, r_i) and candidate discs (z, R) covering p when |x_p - z| - r_p <= R.
struct Disc {
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  double radius = 0;
  std::vector<Eigen::Index> support;
};

class WeightedCentre {
 public:
  WeightedCentre(const MatrixXd& x, const VectorXd& r) : x_(x), r_(r) {}
  Eigen::Vector2d point(Eigen::Index i) const { return x_.row(i).transpose(); }
  double excess(const Disc& d, Eigen::Index i) const { return (point(i) - d.z).norm() - r_(i) - d.radius; }
  bool covers(const Disc& d, Eigen::Index i) const {
    return excess(d, i) <= 1e-12 * (std::abs(d.radius) + std::abs(r_(i)) + (point(i) - d.z).norm());
  }
  Disc from_one(Eigen::Index a) const { return {point(a), -r_(a), {a}}; }
  Disc from_two(Eigen::Index a, Eigen::Index b) const {
    const Eigen::Vector2d u = point(b) - point(a);
    const double length = u.norm();
    if (length == 0.0) return r_(a) <= r_(b) ? from_one(a) : from_one(b);
    // On the segment, where the two excesses agree.
    const double along = std::clamp(0.5 * (length + r_(a) - r_(b)), 0.0, length);
    if (along == 0.0) return from_one(a);
    if (along == length) return from_one(b);
    Disc d{point(a) + along * u / length, along - r_(a), {a, b}};
    return d;
  }
  // The disc with a, b, c on its rim (Apollonius): z = z0 + z1 R from the differences of the
  // three equations |x_i - z| = R + r_i, then a quadratic in R.
  Disc from_three(Eigen::Index a, Eigen::Index b, Eigen::Index c) const {
    Eigen::Matrix2d m;
    m.row(0) = 2.0 * (point(b) - point(a)).transpose();
    m.row(1) = 2.0 * (point(c) - point(a)).transpose();
    const Eigen::Vector2d rhs(point(b).squaredNorm() - point(a).squaredNorm() - r_(b) * r_(b) + r_(a) * r_(a),
                              point(c).squaredNorm() - point(a).squaredNorm() - r_(c) * r_(c) + r_(a) * r_(a));
    const Eigen::Vector2d slope(2.0 * (r_(b) - r_(a)), 2.0 * (r_(c) - r_(a)));
    const Eigen::FullPivLU<Eigen::Matrix2d> lu(m);
    Disc best;
    best.radius = INFINITY;
    if (lu.isInvertible()) {
      const Eigen::Vector2d z0 = lu.solve(rhs), z1 = -lu.solve(slope);
      const Eigen::Vector2d w = z0 - point(a);
      const double qa = z1.squaredNorm() - 1.0, qb = 2.0 * (w.dot(z1) - r_(a)), qc = w.squaredNorm() - r_(a) * r_(a);
      std::vector<double> roots;
      if (std::abs(qa) < 1e-14) {
        if (qb != 0.0) roots.push_back(-qc / qb);
      } else {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc >= 0.0) {
          const double s = std::sqrt(disc);
          roots = {(-qb - s) / (2.0 * qa), (-qb + s) / (2.0 * qa)};
        }
      }
      for (double radius : roots) {
        if (radius + r_(a) < 0 || radius + r_(b) < 0 || radius + r_(c) < 0 || radius >= best.radius) continue;
        best = {z0 + z1 * radius, radius, {a, b, c}};
      }
    }
    if (std::isfinite(best.radius)) return best;
    // Collinear or no tangent disc: the smallest two-point disc that covers the third.
    for (const auto& [p, q, o] : {std::array<Eigen::Index, 3>{a, b, c}, {a, c, b}, {b, c, a}}) {
      const Disc d = from_two(p, q);
      if (covers(d, o) && d.radius < best.radius) best = d;
    }
    return best;
  }

  Disc solve() {
    const Eigen::Index n = x_.rows();
    std::vector<Eigen::Index> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::mt19937 generator(12345);  // a fixed seed: the same samples give the same support
    std::shuffle(order.begin(), order.end(), generator);
    Disc d = from_one(order[0]);
    for (size_t i = 1; i < order.size(); ++i) {
      if (covers(d, order[i])) continue;
      d = from_one(order[i]);
      for (size_t j = 0; j < i; ++j) {
        if (covers(d, order[j])) continue;
        d = from_two(order[i], order[j]);
        for (size_t k = 0; k < j; ++k)
          if (!covers(d, order[k])) d = from_three(order[i], order[j], order[k]);
      }
    }
    return d;
  }

 private:
  const MatrixXd& x_;
  const VectorXd& r_;
};

// z's derivatives at the support: 1 point, z = x_a; 2 points, z on their segment where the
// excesses agree; 3 points, the implicit function theorem on |x_i - z| - r_i = R.
void add_derivatives(const MatrixXd& x, const VectorXd& r, const Disc& d, StickCentre& c) {
  c.support = d.support;
  const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
  if (d.support.size() == 1) {
    c.dz_dx = {identity};
    c.dz_dr = {Eigen::Vector2d::Zero()};
    return;
  }
  if (d.support.size() == 2) {
    const Eigen::Index a = d.support[0], b = d.support[1];
    const Eigen::Vector2d u = (x.row(b) - x.row(a)).transpose();
    const double length = u.norm(), along = 0.5 * (length + r(a) - r(b));
    const Eigen::Vector2d e = u / length;
    const Eigen::Matrix2d across = identity - e * e.transpose();
    const Eigen::Matrix2d to_b = 0.5 * e * e.transpose() + along / length * across;
    c.dz_dx = {identity - to_b, to_b};
    c.dz_dr = {0.5 * e, -0.5 * e};
    return;
  }
  Eigen::Matrix3d k;
  std::array<Eigen::Vector2d, 3> g;
  for (int i = 0; i < 3; ++i) {
    g[static_cast<size_t>(i)] = (d.z - x.row(d.support[static_cast<size_t>(i)]).transpose()).normalized();
    k.row(i) << g[static_cast<size_t>(i)].transpose(), -1.0;
  }
  const Eigen::Matrix3d inverse = k.inverse();
  c.dz_dx.clear();
  c.dz_dr.clear();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d column = inverse.topRows(2).col(i);
    c.dz_dx.push_back(column * g[static_cast<size_t>(i)].transpose());
    c.dz_dr.push_back(column);
  }
}

}  // namespace

StickCentre stick_centre(const MatrixXd& x, const VectorXd& r) {
  // At rest (x and r constant) every sample ties for the support and z is not differentiable:
  // the mean stands in, as in elastic_dry_friction, so that the tangent at rest is the stuck
  // spring on every harmonic but the mean.
  const bool at_rest = (x.rowwise() - x.row(0)).isZero(0.0) && (r.array() == r(0)).all();
  if (at_rest) {
    StickCentre c;
    c.z = x.row(0).transpose();
    c.margin = r(0);
    const Eigen::Index n = x.rows();
    for (Eigen::Index t = 0; t < n; ++t) {
      c.support.push_back(t);
      c.dz_dx.push_back(MatrixXd::Identity(x.cols(), x.cols()) / static_cast<double>(n));
      c.dz_dr.push_back(VectorXd::Zero(x.cols()));
    }
    return c;
  }
  if (x.cols() == 1) return one_direction(x, r);
  if (x.cols() != 2) throw std::invalid_argument("stick_centre: 1 or 2 directions");
  const Disc d = WeightedCentre(x, r).solve();
  StickCentre c;
  c.z = d.z;
  c.margin = -d.radius;
  add_derivatives(x, r, d, c);
  return c;
}

}  // namespace hbtrack
