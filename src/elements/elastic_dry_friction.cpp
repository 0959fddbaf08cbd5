#include "hbtrack/elements/elastic_dry_friction.hpp"

#include <stdexcept>

#include "jenkins_slider.hpp"

namespace hbtrack {

const std::vector<std::string>& ElasticDryFriction::property_names() const {
  static const std::vector<std::string> names{"stiffness", "limit_force"};
  return names;
}

ScalarElement::ScalarLaw ElasticDryFriction::law(double, double, const double*) const {
  throw std::logic_error("elastic_dry_friction has no pointwise law");
}

void ElasticDryFriction::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& /*v*/, double /*omega*/,
                                  const std::vector<double>& props, ElementResponse& out, bool want_property_derivatives) const {
  const Eigen::VectorXd d = x * weights;
  JenkinsPeriod period;
  std::vector<Eigen::Triplet<double>> scalar_terms;  // d f(t) / d d(s)
  scalar_terms.reserve(static_cast<size_t>(3 * d.size()));
  jenkins_period(d, SampledRange(d), props[0], props[1], 1.0, period, scalar_terms);

  out.force = period.force * weights.transpose();
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  spread_scalar_sensitivities(scalar_terms, weights, d.size(), out.history_dforce_dx);
  if (want_property_derivatives) {
    const int k = local_dofs();
    out.dforce_dproperty.resize(d.size(), 2 * k);
    out.dforce_dproperty.leftCols(k) = period.dforce_dstiffness * weights.transpose();
    out.dforce_dproperty.rightCols(k) = period.dforce_dlimit * weights.transpose();
  }
}

void ElasticDryFriction::history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double /*dt*/, double /*omega*/,
                                      const std::vector<double>& props, HistoryStep& out) const {
  const JenkinsStep s = jenkins_step(x.row(0).dot(weights), state(0), props[0], props[1]);
  out.force = s.force * weights;
  out.state = Eigen::VectorXd::Constant(1, s.slider);
  out.diagonal_state = true;
  out.dforce_dx = s.dforce_dd * weights * weights.transpose();
  out.dforce_dstate = s.dforce_dslider * weights;
  out.dstate_dx = s.dslider_dd * weights.transpose();
  out.dstate_dstate = Eigen::MatrixXd::Constant(1, 1, s.dslider_dslider);
}

Eigen::MatrixXd ElasticDryFriction::periodic_history(const Eigen::MatrixXd& x, double /*omega*/, const std::vector<double>& props) const {
  // The slider sits at d - f / k.
  const Eigen::VectorXd d = x * weights;
  JenkinsPeriod period;
  std::vector<Eigen::Triplet<double>> unused;
  jenkins_period(d, SampledRange(d), props[0], props[1], 1.0, period, unused);
  return d - period.force / props[0];
}

}  // namespace hbtrack
