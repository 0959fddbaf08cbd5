#include "hbtrack/elements/iwan.hpp"

#include <cmath>
#include <stdexcept>

#include "jenkins_slider.hpp"

namespace hbtrack {

namespace {
enum Property { kLimitForce, kStiffness, kChi, kBeta };

// s^p and its derivative with respect to p, with 0^p = 0 (p > 0).
double power(double s, double p) { return s > 0 ? std::pow(s, p) : 0.0; }
double power_dp(double s, double p) { return s > 0 ? std::pow(s, p) * std::log(s) : 0.0; }
}  // namespace

Iwan::Iwan(int sliders) : sliders_(sliders) {
  if (sliders < 2) throw std::invalid_argument("iwan: needs at least 2 sliders");
  grid_.resize(sliders + 1);
  grid_(0) = 0.0;
  for (int i = 1; i <= sliders; ++i) grid_(i) = std::pow(10.0, -kDecades * (sliders - i) / (sliders - 1));
}

const std::vector<std::string>& Iwan::property_names() const {
  static const std::vector<std::string> names{"limit_force", "stiffness", "chi", "beta"};
  return names;
}

ScalarElement::ScalarLaw Iwan::law(double, double, const double*) const { throw std::logic_error("iwan has no pointwise law"); }

Iwan::SliderArray Iwan::discretise(const std::vector<double>& props) const {
  const double fs = props[kLimitForce], kt = props[kStiffness], chi = props[kChi], beta = props[kBeta];
  if (!(chi > -1.0) || !(beta >= 0.0) || !(kt > 0.0) || !(fs > 0.0))
    throw std::invalid_argument("iwan: needs limit_force > 0, stiffness > 0, chi > -1 and beta >= 0");
  const int m = sliders_ + 1;
  SliderArray a;
  a.stiffness.resize(m);
  a.limit.resize(m);
  a.dstiffness.setZero(m, 4);
  a.dlimit.setZero(m, 4);
  // Power-law sliders: k_i = K_T (s_i^(chi+1) - s_(i-1)^(chi+1)) / (1 + beta),
  // F_i = F_S g (s_i^(chi+2) - s_(i-1)^(chi+2)), g = (chi+1) / den, den = (chi+2) beta + chi + 1
  // (the integrals of rho and phi rho over the interval, with R and phi_max written through
  // the properties).
  const double den = (chi + 2.0) * beta + chi + 1.0;
  const double g = (chi + 1.0) / den, dg_dchi = beta / (den * den), dg_dbeta = -(chi + 1.0) * (chi + 2.0) / (den * den);
  for (int i = 0; i < sliders_; ++i) {
    const double lo = grid_(i), hi = grid_(i + 1);
    const double p1 = power(hi, chi + 1) - power(lo, chi + 1), dp1 = power_dp(hi, chi + 1) - power_dp(lo, chi + 1);
    const double p2 = power(hi, chi + 2) - power(lo, chi + 2), dp2 = power_dp(hi, chi + 2) - power_dp(lo, chi + 2);
    a.stiffness(i) = kt * p1 / (1.0 + beta);
    a.dstiffness(i, kStiffness) = p1 / (1.0 + beta);
    a.dstiffness(i, kChi) = kt * dp1 / (1.0 + beta);
    a.dstiffness(i, kBeta) = -a.stiffness(i) / (1.0 + beta);
    a.limit(i) = fs * g * p2;
    a.dlimit(i, kLimitForce) = g * p2;
    a.dlimit(i, kChi) = fs * (dg_dchi * p2 + g * dp2);
    a.dlimit(i, kBeta) = fs * dg_dbeta * p2;
  }
  // The Dirac at phi_max: S = K_T beta / (1 + beta), slip force F_S (chi+2) beta / den.
  const int d = sliders_;
  a.stiffness(d) = kt * beta / (1.0 + beta);
  a.dstiffness(d, kStiffness) = beta / (1.0 + beta);
  a.dstiffness(d, kBeta) = kt / ((1.0 + beta) * (1.0 + beta));
  a.limit(d) = fs * (chi + 2.0) * beta / den;
  a.dlimit(d, kLimitForce) = (chi + 2.0) * beta / den;
  a.dlimit(d, kChi) = -fs * dg_dchi;  // the slip forces sum to F_S whatever chi and beta
  a.dlimit(d, kBeta) = -fs * dg_dbeta;
  a.phi_max = fs * (1.0 + beta) / (kt * (beta + (chi + 1.0) / (chi + 2.0)));
  return a;
}

namespace {
// The slider's periodic state. A Dirac slider of zero stiffness (beta = 0) adds no force, but
// its property derivatives need its stick-slip pattern, which its slip length phi_max fixes:
// the pattern of a unit slider with that slip length.
void slider_period(const Eigen::VectorXd& d, const SampledRange& range, double stiffness, double limit, double phi, JenkinsPeriod& out,
                   std::vector<Eigen::Triplet<double>>& terms) {
  if (stiffness > 0) {
    jenkins_period(d, range, stiffness, limit, 1.0, out, terms);
    return;
  }
  std::vector<Eigen::Triplet<double>> none;
  jenkins_period(d, range, 1.0, phi, 0.0, out, none);
  out.force.setZero();
}
}  // namespace

void Iwan::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& /*v*/, double /*omega*/, const std::vector<double>& props,
                    ElementResponse& out, bool want_property_derivatives) const {
  const Eigen::VectorXd d = x * weights;
  const Eigen::Index n = d.size();
  const SampledRange range(d);
  const SliderArray array = discretise(props);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd dforce_dproperty = Eigen::MatrixXd::Zero(n, 4);
  std::vector<Eigen::Triplet<double>> scalar_terms;
  scalar_terms.reserve(static_cast<size_t>(2 * n * (sliders_ + 1)));
  JenkinsPeriod period;
  for (int i = 0; i <= sliders_; ++i) {
    slider_period(d, range, array.stiffness(i), array.limit(i), array.phi_max, period, scalar_terms);
    force += period.force;
    if (want_property_derivatives)
      dforce_dproperty += period.dforce_dstiffness * array.dstiffness.row(i) + period.dforce_dlimit * array.dlimit.row(i);
  }
  out.force = force * weights.transpose();
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  spread_scalar_sensitivities(scalar_terms, weights, n, out.history_dforce_dx);
  if (want_property_derivatives) {
    const int k = local_dofs();
    out.dforce_dproperty.resize(n, 4 * k);
    for (int p = 0; p < 4; ++p) out.dforce_dproperty.middleCols(p * k, k) = dforce_dproperty.col(p) * weights.transpose();
  }
}

void Iwan::history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double /*dt*/, double /*omega*/,
                        const std::vector<double>& props, HistoryStep& out) const {
  // Time stepping calls this once per step with the same properties: the array (a few hundred
  // powers) is kept per thread for the last slider count and properties seen, which fix it.
  thread_local struct {
    int sliders = 0;
    std::vector<double> props;
    SliderArray array;
  } cache;
  if (cache.sliders != sliders_ || cache.props != props) {
    cache.array = discretise(props);
    cache.sliders = sliders_;
    cache.props = props;
  }
  const SliderArray& array = cache.array;
  const int m = sliders_ + 1;
  const double d = x.row(0).dot(weights);
  double force = 0, dforce_dd = 0;
  out.state.resize(m);
  out.dforce_dstate.resize(local_dofs(), m);
  out.dstate_dx.resize(m, local_dofs());
  out.dstate_dstate.setZero(m, m);
  out.diagonal_state = true;
  for (int i = 0; i < m; ++i) {
    const JenkinsStep s = jenkins_step(d, state(i), array.stiffness(i), array.limit(i));
    force += s.force;
    dforce_dd += s.dforce_dd;
    out.state(i) = s.slider;
    out.dforce_dstate.col(i) = s.dforce_dslider * weights;
    out.dstate_dx.row(i) = s.dslider_dd * weights.transpose();
    out.dstate_dstate(i, i) = s.dslider_dslider;
  }
  out.force = force * weights;
  out.dforce_dx = dforce_dd * weights * weights.transpose();
}

Eigen::MatrixXd Iwan::periodic_history(const Eigen::MatrixXd& x, double /*omega*/, const std::vector<double>& props) const {
  const Eigen::VectorXd d = x * weights;
  const SampledRange range(d);
  const SliderArray array = discretise(props);
  Eigen::MatrixXd state(d.size(), sliders_ + 1);
  JenkinsPeriod period;
  std::vector<Eigen::Triplet<double>> unused;
  for (int i = 0; i <= sliders_; ++i) {
    if (array.stiffness(i) == 0) {  // the Dirac slider at beta = 0: no force, it never moves
      state.col(i).setZero();
      continue;
    }
    jenkins_period(d, range, array.stiffness(i), array.limit(i), 0.0, period, unused);
    state.col(i) = d - period.force / array.stiffness(i);
    unused.clear();
  }
  return state;
}

}  // namespace hbtrack
