#include "hbtrack/elements/scalar_elements.hpp"

#include <cmath>
#include <numbers>

namespace hbtrack {

void ScalarElement::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& v, double omega, const std::vector<double>& props,
                             ElementResponse& out, bool want_property_derivatives) const {
  const Eigen::Index n = x.rows();
  const int k = local_dofs();
  const int np = static_cast<int>(props.size());
  const bool with_v = depends_on_velocity();
  // A whole period of samples (n > 1, the AFT): a law with a corner is averaged over each
  // sample (sample_mean_law); one instant (time integration) gets the law itself.
  const bool averaged = n > 1 && averages_over_samples(props);
  // h = (pi / N) dd/dtau = pi dd / (omega N): d h / d v and the explicit d h / d omega.
  const double dh_dv = averaged ? std::numbers::pi / (omega * static_cast<double>(n)) : 0.0;
  out.force.resize(n, k);
  out.dforce_dx.resize(n, k * k);
  if (with_v)
    out.dforce_dv.resize(n, k * k);
  else
    out.dforce_dv.resize(0, 0);
  if (averaged)
    out.dforce_domega.resize(n, k);
  else
    out.dforce_domega.resize(0, 0);
  if (want_property_derivatives) out.dforce_dproperty.resize(n, k * np);
  for (Eigen::Index t = 0; t < n; ++t) {
    double d = 0, dd = 0;
    for (int i = 0; i < k; ++i) {
      d += weights(i) * x(t, i);
      if (with_v) dd += weights(i) * v(t, i);
    }
    ScalarLaw law_value;
    double df_domega = 0;
    if (averaged) {
      const double h = dd * dh_dv;
      sample_mean_law(d, h, props.data(), law_value);
      df_domega = -law_value.df_dv * h / omega;
      law_value.df_dv *= dh_dv;
    } else {
      law_value = law(d, dd, props.data());
    }
    for (int i = 0; i < k; ++i) {
      out.force(t, i) = weights(i) * law_value.f;
      if (averaged) out.dforce_domega(t, i) = weights(i) * df_domega;
      for (int j = 0; j < k; ++j) {
        out.dforce_dx(t, i + k * j) = weights(i) * weights(j) * law_value.df_dd;
        if (with_v) out.dforce_dv(t, i + k * j) = weights(i) * weights(j) * law_value.df_dv;
      }
      if (want_property_derivatives)
        for (int p = 0; p < np; ++p) out.dforce_dproperty(t, i + k * p) = weights(i) * law_value.df_dp[p];
    }
  }
}

const std::vector<std::string>& CubicSpring::property_names() const {
  static const std::vector<std::string> names{"cubic_stiffness"};
  return names;
}

ScalarElement::ScalarLaw CubicSpring::law(double d, double, const double* p) const {
  ScalarLaw out;
  out.f = p[0] * d * d * d;
  out.df_dd = 3.0 * p[0] * d * d;
  out.df_dp[0] = d * d * d;
  return out;
}

const std::vector<std::string>& GapContact::property_names() const {
  static const std::vector<std::string> names{"stiffness", "gap", "width"};
  return names;
}

ScalarElement::ScalarLaw GapContact::law(double d, double, const double* p) const {
  const ContactForce c = contact_force(kind_, d - p[1], p[0], p[2]);
  ScalarLaw out;
  out.f = c.force;
  out.df_dd = c.d_gap;
  out.df_dp[0] = c.d_stiffness;
  out.df_dp[1] = -c.d_gap;
  out.df_dp[2] = c.d_width;
  return out;
}

bool GapContact::sample_mean_law(double d, double h, const double* p, ScalarLaw& out) const {
  // Mean of k max(g, 0) for g from g0 - |h| to g0 + |h| (even in h), in closed form per case so
  // that nothing cancels: all in contact, none, or straddling the corner.
  const double k = p[0], g = d - p[1], a = std::abs(h);
  out = ScalarLaw{};
  if (g - a >= 0.0) {
    out.f = k * g;
    out.df_dd = k;
  } else if (g + a > 0.0) {
    const double b = g + a;  // > 0, and a > 0 here
    out.f = k * b * b / (4.0 * a);
    out.df_dd = k * b / (2.0 * a);
    out.df_dv = (h < 0 ? -1.0 : 1.0) * k * b * (a - g) / (4.0 * a * a);
  }
  out.df_dp[0] = k > 0 ? out.f / k : 0.0;
  out.df_dp[1] = -out.df_dd;
  return true;
}

int GapContact::switching_surfaces(const std::vector<double>& p) const { return kind_ == ContactLawKind::penalty || p[2] <= 0.0 ? 1 : 0; }

void GapContact::switching_values(const Eigen::MatrixXd& x, const Eigen::MatrixXd&, const std::vector<double>& p, double* out) const {
  out[0] = x.row(0).dot(weights) - p[1];
}

const std::vector<std::string>& TanhFriction::property_names() const {
  static const std::vector<std::string> names{"mu", "normal_load", "regularization_velocity"};
  return names;
}

ScalarElement::ScalarLaw TanhFriction::law(double, double d_dot, const double* p) const {
  const double mu = p[0], load = p[1], vr = p[2];
  const double t = std::tanh(d_dot / vr);
  const double sech2 = 1.0 - t * t;
  ScalarLaw out;
  out.f = mu * load * t;
  out.df_dv = mu * load * sech2 / vr;
  out.df_dp[0] = load * t;
  out.df_dp[1] = mu * t;
  out.df_dp[2] = -mu * load * sech2 * d_dot / (vr * vr);
  return out;
}

}  // namespace hbtrack
