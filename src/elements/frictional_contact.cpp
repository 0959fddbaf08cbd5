#include "hbtrack/elements/frictional_contact.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "coulomb_slider.hpp"
#include "penalty_contact_period.hpp"

namespace hbtrack {

namespace {

enum Property { kNormalStiffness, kTangentialStiffness, kMu, kNormalPreload };

// N = max(0, preload + kn x_n) and dN/dx_n.
struct NormalLoad {
  double force = 0, slope = 0;
};
NormalLoad normal_load(const std::vector<double>& props, double xn) {
  const double s = props[kNormalPreload] + props[kNormalStiffness] * xn;
  return s > 0.0 ? NormalLoad{s, props[kNormalStiffness]} : NormalLoad{};
}

}  // namespace

FrictionalContact::FrictionalContact(ContactFormulation law, int directions) : law_(law), directions_(directions) {
  if (directions != 1 && directions != 2) throw std::invalid_argument("frictional_contact: 1 or 2 tangential directions");
  if (directions == 2 && law == ContactFormulation::dlft) throw std::invalid_argument("frictional_contact_2d: the penalty law only");
}

ContactFormulation parse_contact_formulation(const std::string& name) {
  if (name == "penalty") return ContactFormulation::penalty;
  if (name == "dlft") return ContactFormulation::dlft;
  throw std::invalid_argument("must be \"penalty\" or \"dlft\", got \"" + name + "\"");
}

const std::vector<std::string>& FrictionalContact::property_names() const {
  static const std::vector<std::string> penalty{"normal_stiffness", "tangential_stiffness", "mu", "normal_preload"};
  static const std::vector<std::string> dlft{"mu", "epsilon", "gap"};
  return law_ == ContactFormulation::penalty ? penalty : dlft;
}

std::optional<FrictionCoupling> FrictionalContact::friction_coupling(const std::vector<double>& props, double /*omega*/) const {
  if (directions_ == 2) return std::nullopt;  // the loop gain's coupling has one tangential direction
  if (law_ == ContactFormulation::dlft) return FrictionCoupling{0, 1, props[0], 0.0, 0};  // properties mu, epsilon, gap
  return FrictionCoupling{0, 1, props[kMu], props[kNormalStiffness], 0};
}

void FrictionalContact::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& /*v*/, double /*omega*/, const std::vector<double>& props,
                                 ElementResponse& out, bool want_property_derivatives) const {
  if (local_dofs() != 1 + directions_ || x.cols() != 1 + directions_)
    throw std::invalid_argument(type() + ": needs " + std::to_string(1 + directions_) + " dofs [normal, tangential...]");
  if (law_ == ContactFormulation::dlft) throw std::logic_error("frictional_contact with law = \"dlft\" needs the linear residual");
  penalty_contact_period(x, props, out, want_property_derivatives);
}

void penalty_contact_period(const Eigen::MatrixXd& x, const std::vector<double>& props, ElementResponse& out,
                            bool want_property_derivatives) {
  out.residual_operator.reset();
  const Eigen::Index n = x.rows();
  const int d = static_cast<int>(x.cols()) - 1;  // tangential directions
  Eigen::VectorXd normal(n), slope(n);
  for (Eigen::Index t = 0; t < n; ++t) {
    const NormalLoad load = normal_load(props, x(t, 0));
    normal(t) = load.force;
    slope(t) = load.slope;
  }
  CoulombSlider slider(d, props[kTangentialStiffness], props[kMu]);
  slider.solve_period(normal, x.rightCols(d), Eigen::VectorXd::Zero(d));

  out.force.resize(n, 1 + d);
  out.force.col(0) = normal;
  for (Eigen::Index t = 0; t < n; ++t) out.force.row(t).tail(d) = slider.steps()[static_cast<size_t>(t)].force.transpose();
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  out.history_dforce_dx.resize(0, 0);
  if (want_property_derivatives) {
    // Each property as a perturbation of the slider's inputs: kn and the preload through N
    // (x_n and 1 in contact), mu and kt directly.
    const int q = slider.inputs();
    Eigen::MatrixXd dv = Eigen::MatrixXd::Zero(n * q, 4);
    for (Eigen::Index t = 0; t < n; ++t) {
      const bool contact = normal(t) > 0.0;
      dv(t * q + slider.normal_input(), kNormalStiffness) = contact ? x(t, 0) : 0.0;
      dv(t * q + slider.normal_input(), kNormalPreload) = contact ? 1.0 : 0.0;
      dv(t * q + slider.mu_input(), kMu) = 1.0;
      dv(t * q + slider.stiffness_input(), kTangentialStiffness) = 1.0;
    }
    const Eigen::MatrixXd dt = slider.periodic_response(dv);
    out.dforce_dproperty.setZero(n, 4 * (1 + d));
    for (int p = 0; p < 4; ++p)
      for (Eigen::Index t = 0; t < n; ++t) {
        out.dforce_dproperty(t, (1 + d) * p) = dv(t * q + slider.normal_input(), p);
        for (int i = 0; i < d; ++i) out.dforce_dproperty(t, (1 + d) * p + 1 + i) = dt(t * d + i, p);
      }
  }
  out.history_operator = std::make_shared<ContactSliderSensitivity>(std::move(slider), std::move(slope));
}

void FrictionalContact::history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double dt, double omega,
                                     const std::vector<double>& props, HistoryStep& out) const {
  if (law_ == ContactFormulation::dlft) {
    NonlinearElement::history_step(x, state, dt, omega, props, out);
    return;
  }
  const NormalLoad load = normal_load(props, x(0, 0));
  contact_slider_step(CoulombSlider(directions_, props[kTangentialStiffness], props[kMu]), load.force, load.slope, x,
                      Eigen::VectorXd::Zero(directions_), state, out);
}

Eigen::MatrixXd FrictionalContact::periodic_history(const Eigen::MatrixXd& x, double omega, const std::vector<double>& props) const {
  if (law_ == ContactFormulation::dlft) return NonlinearElement::periodic_history(x, omega, props);
  Eigen::VectorXd normal(x.rows());
  for (Eigen::Index t = 0; t < x.rows(); ++t) normal(t) = normal_load(props, x(t, 0)).force;
  CoulombSlider slider(directions_, props[kTangentialStiffness], props[kMu]);
  slider.solve_period(normal, x.rightCols(directions_), Eigen::VectorXd::Zero(directions_));
  Eigen::MatrixXd z(x.rows(), directions_);
  for (Eigen::Index t = 0; t < x.rows(); ++t) z.row(t) = slider.steps()[static_cast<size_t>(t)].state.transpose();
  return z;
}

}  // namespace hbtrack
