#include "jenkins_slider.hpp"

namespace hbtrack {

void jenkins_period(const Eigen::VectorXd& d, const SampledRange& range, double stiffness, double limit, double scale, JenkinsPeriod& out,
                    std::vector<Eigen::Triplet<double>>& terms) {
  const Eigen::Index n = d.size();
  out.force.resize(n);
  out.dforce_dstiffness.resize(n);
  out.dforce_dlimit.resize(n);
  // f(t) = stiffness * (d(t) - anchor(t)) + offset(t), anchor(t) a combination of at most two
  // samples of d.
  if (stiffness * (range.max - range.min) > 2.0 * limit) {
    // At the largest d the force is +F whatever came before: one pass from there is periodic.
    Eigen::Index anchor = range.imax;
    double direction = 1.0;
    double slider = range.max - limit / stiffness;
    for (Eigen::Index step = 0; step < n; ++step) {
      const Eigen::Index t = (range.imax + step) % n;
      const double trial = stiffness * (d(t) - slider);
      if (step == 0 || trial > limit) {
        anchor = t, direction = 1.0, slider = d(t) - limit / stiffness;
      } else if (trial < -limit) {
        anchor = t, direction = -1.0, slider = d(t) + limit / stiffness;
      }
      if (anchor == t) {  // slipping: f = +-F, independent of d
        out.force(t) = direction * limit;
        out.dforce_dstiffness(t) = 0.0;
      } else {
        out.force(t) = stiffness * (d(t) - d(anchor)) + direction * limit;
        out.dforce_dstiffness(t) = d(t) - d(anchor);
        terms.emplace_back(t, t, scale * stiffness);
        terms.emplace_back(t, anchor, -scale * stiffness);
      }
      out.dforce_dlimit(t) = direction;
    }
    return;
  }
  // Stuck over the whole period: the slider rests anywhere that keeps |f| <= F, a history the
  // periodic problem does not see; it is put midway between the extremes. When d does not move
  // at all (at rest) the extremes are not differentiable: the mean stands in, so that the
  // tangent at rest is the stuck spring on every harmonic but the mean.
  const double middle = 0.5 * (range.max + range.min);
  const bool at_rest = range.max == range.min;
  for (Eigen::Index t = 0; t < n; ++t) {
    out.force(t) = stiffness * (d(t) - middle);
    out.dforce_dstiffness(t) = d(t) - middle;
    out.dforce_dlimit(t) = 0.0;
    terms.emplace_back(t, t, scale * stiffness);
    if (at_rest) {
      for (Eigen::Index s = 0; s < n; ++s) terms.emplace_back(t, s, -scale * stiffness / static_cast<double>(n));
    } else {
      terms.emplace_back(t, range.imax, -0.5 * scale * stiffness);
      terms.emplace_back(t, range.imin, -0.5 * scale * stiffness);
    }
  }
}

void spread_scalar_sensitivities(const std::vector<Eigen::Triplet<double>>& scalar_terms, const Eigen::VectorXd& weights,
                                 Eigen::Index samples, Eigen::SparseMatrix<double>& out) {
  const Eigen::Index k = weights.size();
  std::vector<Eigen::Triplet<double>> terms;
  terms.reserve(scalar_terms.size() * static_cast<size_t>(k * k));
  for (const auto& term : scalar_terms)
    for (Eigen::Index i = 0; i < k; ++i)
      for (Eigen::Index j = 0; j < k; ++j) {
        const double w = weights(i) * weights(j);
        if (w != 0.0) terms.emplace_back(term.row() + samples * i, term.col() + samples * j, w * term.value());
      }
  out.resize(samples * k, samples * k);
  out.setFromTriplets(terms.begin(), terms.end());  // sums repeated entries
}

JenkinsStep jenkins_step(double d, double slider, double stiffness, double limit) {
  JenkinsStep s;
  const double trial = stiffness * (d - slider);
  if (trial > limit || trial < -limit) {
    const double direction = trial > 0 ? 1.0 : -1.0;
    s.force = direction * limit;
    s.slider = d - s.force / stiffness;
    s.dslider_dd = 1.0;
    return s;
  }
  s.force = trial;
  s.slider = slider;
  s.dforce_dd = stiffness;
  s.dforce_dslider = -stiffness;
  s.dslider_dslider = 1.0;
  return s;
}

}  // namespace hbtrack
