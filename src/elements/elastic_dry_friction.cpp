#include "hbtrack/elements/elastic_dry_friction.hpp"

#include <stdexcept>

namespace hbtrack {

const std::vector<std::string>& ElasticDryFriction::property_names() const {
  static const std::vector<std::string> names{"stiffness", "limit_force"};
  return names;
}

ScalarElement::ScalarLaw ElasticDryFriction::law(double, double, const double*) const {
  throw std::logic_error("elastic_dry_friction has no pointwise law");
}

void ElasticDryFriction::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& /*v*/, double /*omega*/,
                                  const std::vector<double>& props, ElementResponse& out,
                                  bool want_property_derivatives) const {
  const Eigen::Index n = x.rows();
  const int k = local_dofs();
  const double stiffness = props[0], limit = props[1];
  const Eigen::VectorXd d = x * weights;
  Eigen::Index imax = 0, imin = 0;
  const double dmax = d.maxCoeff(&imax), dmin = d.minCoeff(&imin);

  // Scalar force and its sensitivities: f(t) = stiffness * (d(t) - anchor(t)) + offset(t),
  // anchor(t) = sum of weight * d(sample) over at most two samples.
  Eigen::VectorXd f(n), df_dk(n), df_dlimit(n);
  std::vector<Eigen::Triplet<double>> scalar_terms;  // d f(t) / d d(s)
  scalar_terms.reserve(static_cast<size_t>(3 * n));
  if (stiffness * (dmax - dmin) > 2.0 * limit) {
    Eigen::Index anchor = imax;
    double direction = 1.0;
    double slider = dmax - limit / stiffness;
    for (Eigen::Index step = 0; step < n; ++step) {
      const Eigen::Index t = (imax + step) % n;
      const double trial = stiffness * (d(t) - slider);
      if (step == 0 || trial > limit) {
        anchor = t, direction = 1.0, slider = d(t) - limit / stiffness;
      } else if (trial < -limit) {
        anchor = t, direction = -1.0, slider = d(t) + limit / stiffness;
      }
      if (anchor == t) {  // slipping: f = +-F, independent of d
        f(t) = direction * limit;
        df_dk(t) = 0.0;
      } else {
        f(t) = stiffness * (d(t) - d(anchor)) + direction * limit;
        df_dk(t) = d(t) - d(anchor);
        scalar_terms.emplace_back(t, t, stiffness);
        scalar_terms.emplace_back(t, anchor, -stiffness);
      }
      df_dlimit(t) = direction;
    }
  } else {
    // Stuck over the whole period: the slider rests anywhere that keeps |f| <= F, a history the
    // periodic problem does not see; it is put midway between the extremes. When d does not move
    // at all (at rest) the extremes are not differentiable: the mean stands in, so that the
    // tangent at rest is the stuck spring on every harmonic but the mean.
    const double middle = 0.5 * (dmax + dmin);
    const bool at_rest = dmax == dmin;
    for (Eigen::Index t = 0; t < n; ++t) {
      f(t) = stiffness * (d(t) - middle);
      df_dk(t) = d(t) - middle;
      df_dlimit(t) = 0.0;
      scalar_terms.emplace_back(t, t, stiffness);
      if (at_rest) {
        for (Eigen::Index s = 0; s < n; ++s) scalar_terms.emplace_back(t, s, -stiffness / static_cast<double>(n));
      } else {
        scalar_terms.emplace_back(t, imax, -0.5 * stiffness);
        scalar_terms.emplace_back(t, imin, -0.5 * stiffness);
      }
    }
  }

  out.force = f * weights.transpose();
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  std::vector<Eigen::Triplet<double>> terms;
  terms.reserve(scalar_terms.size() * static_cast<size_t>(k * k));
  for (const auto& term : scalar_terms)
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const double w = weights(i) * weights(j);
        if (w != 0.0) terms.emplace_back(term.row() + n * i, term.col() + n * j, w * term.value());
      }
  out.history_dforce_dx.resize(n * k, n * k);
  out.history_dforce_dx.setFromTriplets(terms.begin(), terms.end());  // sums repeated entries
  if (want_property_derivatives) {
    out.dforce_dproperty.resize(n, 2 * k);
    out.dforce_dproperty.leftCols(k) = df_dk * weights.transpose();
    out.dforce_dproperty.rightCols(k) = df_dlimit * weights.transpose();
  }
}

}  // namespace hbtrack
