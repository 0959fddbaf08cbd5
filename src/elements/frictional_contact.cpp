#include "hbtrack/elements/frictional_contact.hpp"

#include <algorithm>
#include <stdexcept>

namespace hbtrack {

namespace {

enum class Mode { stick, slip, separated };

// One sample of the tangential law. Stick samples point to the event they hang on.
struct Sample {
  Mode mode = Mode::stick;
  double force = 0;      // T
  Eigen::Index anchor = -1;  // stick: last event sample, -1 for the permanent-stick midrange
  double direction = 0;  // slip (or stick after a slip): sign of T at the event
  bool anchor_slipped = false;
};

struct Law {
  double kn, kt, mu, preload;
  double normal(double xn) const { return std::max(0.0, preload + kn * xn); }
};

// The slider's state between samples: position z and the last event (slip or separation).
struct Slider {
  double z = 0;
  Eigen::Index last_event = -1;
  double direction = 0;
  bool last_slipped = false;
};

// One step of the law at sample t; updates the slider.
Sample step(const Law& law, double xn, double xt, Eigen::Index t, Slider& slider) {
  const double normal = law.normal(xn);
  Sample s;
  if (normal <= 0.0) {
    s.mode = Mode::separated;
    slider = Slider{xt, t, 0.0, false};
    return s;
  }
  const double trial = law.kt * (xt - slider.z), limit = law.mu * normal;
  if (trial > limit || trial < -limit) {
    s.mode = Mode::slip;
    s.direction = trial > 0 ? 1.0 : -1.0;
    s.force = s.direction * limit;
    slider = Slider{xt - s.force / law.kt, t, s.direction, true};
    return s;
  }
  s.force = trial;
  s.anchor = slider.last_event;
  s.direction = slider.direction;
  s.anchor_slipped = slider.last_slipped;
  return s;
}

// The periodic steady state of the slider over the samples. A pass from the midrange finds an
// event (or proves a permanent stick); a pass started at the last event, whose state the event
// fixes, is periodic when that event recurs on coming back to it, else it restarts at the new
// last event.
std::vector<Sample> periodic_state(const Law& law, const Eigen::VectorXd& xn, const Eigen::VectorXd& xt, double middle) {
  const Eigen::Index n = xn.size();
  std::vector<Sample> samples(static_cast<size_t>(n));
  Slider slider{middle, -1, 0.0, false};
  for (Eigen::Index t = 0; t < n; ++t) samples[static_cast<size_t>(t)] = step(law, xn(t), xt(t), t, slider);
  for (int attempt = 0; attempt < 50 && slider.last_event >= 0; ++attempt) {
    const Eigen::Index start = slider.last_event;
    // The state after the start event (it does not depend on what came before).
    const Sample& event = samples[static_cast<size_t>(start)];
    slider = event.mode == Mode::separated ? Slider{xt(start), start, 0.0, false}
                                           : Slider{xt(start) - event.force / law.kt, start, event.direction, true};
    for (Eigen::Index k = 1; k < n; ++k) {
      const Eigen::Index t = (start + k) % n;
      samples[static_cast<size_t>(t)] = step(law, xn(t), xt(t), t, slider);
    }
    const Slider before = slider;
    const Sample closing = step(law, xn(start), xt(start), start, slider);
    const bool same_event = closing.mode == event.mode && closing.direction == event.direction;
    // A stick at the start with no event since: the slider rests where the event left it.
    const bool resting = closing.mode == Mode::stick && before.last_event == start;
    if (same_event || resting) break;
    samples[static_cast<size_t>(start)] = closing;
    if (closing.mode == Mode::stick) slider = before;  // restart at the last event of the pass
  }
  return samples;
}

}  // namespace

void FrictionalContact::history_step(const Eigen::MatrixXd& x, const Eigen::VectorXd& state, double /*dt*/, double /*omega*/,
                                     const std::vector<double>& props, HistoryStep& out) const {
  const Law law{props[0], props[1], props[2], props[3]};
  Slider slider{state(0), -1, 0.0, false};
  const double xn = x(0, 0), xt = x(0, 1);
  const Sample s = step(law, xn, xt, 0, slider);
  out.force = Eigen::Vector2d(law.normal(xn), s.mode == Mode::separated ? 0.0 : s.force);
  out.state = Eigen::VectorXd::Constant(1, slider.z);
  out.dforce_dx.setZero(2, 2);
  out.dforce_dstate.setZero(2, 1);
  out.dstate_dx.setZero(1, 2);
  out.dstate_dstate.setZero(1, 1);
  out.diagonal_state = true;
  if (s.mode == Mode::separated) {  // the slider follows x_t
    out.dstate_dx(0, 1) = 1.0;
    return;
  }
  out.dforce_dx(0, 0) = law.kn;
  if (s.mode == Mode::stick) {
    out.dforce_dx(1, 1) = law.kt;
    out.dforce_dstate(1, 0) = -law.kt;
    out.dstate_dstate(0, 0) = 1.0;
    return;
  }
  // Slip: T = sign mu N(x_n), the slider at x_t - T / k_t.
  out.dforce_dx(1, 0) = s.direction * law.mu * law.kn;
  out.dstate_dx(0, 1) = 1.0;
  out.dstate_dx(0, 0) = -s.direction * law.mu * law.kn / law.kt;
}

Eigen::MatrixXd FrictionalContact::periodic_history(const Eigen::MatrixXd& x, double /*omega*/, const std::vector<double>& props) const {
  // The slider sits at x_t - T / k_t in contact and at x_t when separated.
  ElementResponse r;
  evaluate(x, x, 0.0, props, r, false);
  Eigen::MatrixXd z = x.col(1) - r.force.col(1) / props[1];
  for (Eigen::Index t = 0; t < x.rows(); ++t)
    if (r.force(t, 0) <= 0.0) z(t, 0) = x(t, 1);
  return z;
}

const std::vector<std::string>& FrictionalContact::property_names() const {
  static const std::vector<std::string> names{"normal_stiffness", "tangential_stiffness", "mu", "normal_preload"};
  return names;
}

void FrictionalContact::evaluate(const Eigen::MatrixXd& x, const Eigen::MatrixXd& /*v*/, double /*omega*/,
                                 const std::vector<double>& props, ElementResponse& out, bool want_property_derivatives) const {
  if (local_dofs() != 2 || x.cols() != 2) throw std::invalid_argument("frictional_contact: needs 2 dofs [normal, tangential]");
  const Eigen::Index n = x.rows();
  const Law law{props[0], props[1], props[2], props[3]};
  const Eigen::VectorXd xn = x.col(0), xt = x.col(1);
  Eigen::Index imax = 0, imin = 0;
  const double middle = 0.5 * (xt.maxCoeff(&imax) + xt.minCoeff(&imin));

  const std::vector<Sample> samples = periodic_state(law, xn, xt, middle);

  out.force.resize(n, 2);
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  if (want_property_derivatives) out.dforce_dproperty.setZero(n, 8);
  std::vector<Eigen::Triplet<double>> terms;
  terms.reserve(static_cast<size_t>(5 * n));
  const Eigen::Index tn = n;  // offset of the tangential rows/columns
  for (Eigen::Index t = 0; t < n; ++t) {
    const Sample& s = samples[static_cast<size_t>(t)];
    const double normal = law.normal(xn(t));
    const bool contact = normal > 0.0;
    out.force(t, 0) = normal;
    out.force(t, 1) = s.mode == Mode::separated ? 0.0 : s.force;
    if (contact) terms.emplace_back(t, t, law.kn);
    auto d_property = [&](int component, int property) -> double& { return out.dforce_dproperty(t, component + 2 * property); };
    if (want_property_derivatives && contact) {
      d_property(0, 0) = xn(t);
      d_property(0, 3) = 1.0;
    }
    if (s.mode == Mode::slip) {
      terms.emplace_back(tn + t, t, s.direction * law.mu * law.kn);
      if (want_property_derivatives) {
        d_property(1, 0) = s.direction * law.mu * xn(t);
        d_property(1, 2) = s.direction * normal;
        d_property(1, 3) = s.direction * law.mu;
      }
    } else if (s.mode == Mode::stick) {
      const Eigen::Index a = s.anchor;
      terms.emplace_back(tn + t, tn + t, law.kt);
      if (a < 0) {  // permanent stick, slider at the midrange
        terms.emplace_back(tn + t, tn + imax, -0.5 * law.kt);
        terms.emplace_back(tn + t, tn + imin, -0.5 * law.kt);
        if (want_property_derivatives) d_property(1, 1) = xt(t) - middle;
        continue;
      }
      terms.emplace_back(tn + t, tn + a, -law.kt);
      if (want_property_derivatives) d_property(1, 1) = xt(t) - xt(a);
      if (s.anchor_slipped) {  // T = kt (xt(t) - xt(a)) + sigma mu N(a)
        terms.emplace_back(tn + t, a, s.direction * law.mu * law.kn);
        if (want_property_derivatives) {
          d_property(1, 0) = s.direction * law.mu * xn(a);
          d_property(1, 2) = s.direction * law.normal(xn(a));
          d_property(1, 3) = s.direction * law.mu;
        }
      }
    }
  }
  out.history_dforce_dx.resize(2 * n, 2 * n);
  out.history_dforce_dx.setFromTriplets(terms.begin(), terms.end());
}

}  // namespace hbtrack
