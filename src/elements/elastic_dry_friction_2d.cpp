#include "hbtrack/elements/elastic_dry_friction_2d.hpp"

#include <memory>
#include <stdexcept>

#include "coulomb_slider.hpp"

namespace hbtrack {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// The slider of limit F as the Coulomb slider of mu = 1 under the constant load N = F (F = 0:
// "separated", no force, the slider following u).
CoulombSlider planar_slider(const std::vector<double>& props) { return CoulombSlider(2, props[0], 1.0); }

// d f / d x of the element: the slider's periodic response to du = W dx, spread back by W^T.
// Layouts of HistorySensitivity: rows t + N i over the element's k dofs.
class PlanarSliderSensitivity final : public HistorySensitivity {
 public:
  PlanarSliderSensitivity(CoulombSlider slider, MatrixXd weights) : slider_(std::move(slider)), weights_(std::move(weights)) {}

  MatrixXd apply(const MatrixXd& dx) const override {
    const Eigen::Index n = static_cast<Eigen::Index>(slider_.steps().size());
    const int q = slider_.inputs();
    MatrixXd dv = MatrixXd::Zero(n * q, dx.cols());
    for (Eigen::Index t = 0; t < n; ++t)
      for (int j = 0; j < 2; ++j)
        for (Eigen::Index i = 0; i < weights_.cols(); ++i)
          if (weights_(j, i) != 0.0) dv.row(t * q + slider_.x_input(j)) += weights_(j, i) * dx.row(i * n + t);
    const MatrixXd dt = slider_.periodic_response(dv);
    MatrixXd out = MatrixXd::Zero(dx.rows(), dx.cols());
    for (Eigen::Index t = 0; t < n; ++t)
      for (int j = 0; j < 2; ++j)
        for (Eigen::Index i = 0; i < weights_.cols(); ++i)
          if (weights_(j, i) != 0.0) out.row(i * n + t) += weights_(j, i) * dt.row(t * 2 + j);
    return out;
  }

  MatrixXd apply_transpose(const MatrixXd& w) const override {
    const Eigen::Index n = static_cast<Eigen::Index>(slider_.steps().size());
    const int q = slider_.inputs();
    MatrixXd wt = MatrixXd::Zero(n * 2, w.cols());
    for (Eigen::Index t = 0; t < n; ++t)
      for (int j = 0; j < 2; ++j)
        for (Eigen::Index i = 0; i < weights_.cols(); ++i)
          if (weights_(j, i) != 0.0) wt.row(t * 2 + j) += weights_(j, i) * w.row(i * n + t);
    const MatrixXd dv = slider_.periodic_response_transpose(wt);
    MatrixXd out = MatrixXd::Zero(w.rows(), w.cols());
    for (Eigen::Index t = 0; t < n; ++t)
      for (int j = 0; j < 2; ++j)
        for (Eigen::Index i = 0; i < weights_.cols(); ++i)
          if (weights_(j, i) != 0.0) out.row(i * n + t) += weights_(j, i) * dv.row(t * q + slider_.x_input(j));
    return out;
  }

 private:
  CoulombSlider slider_;
  MatrixXd weights_;
};

}  // namespace

const std::vector<std::string>& ElasticDryFriction2D::property_names() const {
  static const std::vector<std::string> names{"stiffness", "limit_force"};
  return names;
}

void ElasticDryFriction2D::evaluate(const MatrixXd& x, const MatrixXd& /*v*/, double /*omega*/, const std::vector<double>& props,
                                    ElementResponse& out, bool want_property_derivatives) const {
  if (weights.rows() != 2 || weights.cols() != x.cols())
    throw std::invalid_argument("elastic_dry_friction_2d: weights must be 2 x (number of dofs)");
  const Eigen::Index n = x.rows();
  const MatrixXd u = x * weights.transpose();  // N x 2
  CoulombSlider slider = planar_slider(props);
  slider.solve_period(VectorXd::Constant(n, props[1]), u, VectorXd::Zero(2));

  MatrixXd tangential(n, 2);
  for (Eigen::Index t = 0; t < n; ++t) tangential.row(t) = slider.steps()[static_cast<size_t>(t)].force.transpose();
  out.force = tangential * weights;
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  out.history_dforce_dx.resize(0, 0);
  out.residual_operator.reset();
  if (want_property_derivatives) {
    // stiffness through the slider's k, limit_force through its load N (mu = 1).
    const int q = slider.inputs();
    MatrixXd dv = MatrixXd::Zero(n * q, 2);
    for (Eigen::Index t = 0; t < n; ++t) {
      dv(t * q + slider.stiffness_input(), 0) = 1.0;
      dv(t * q + slider.normal_input(), 1) = 1.0;
    }
    const MatrixXd dt = slider.periodic_response(dv);
    const int k = local_dofs();
    out.dforce_dproperty.resize(n, 2 * k);
    for (int p = 0; p < 2; ++p) {
      MatrixXd dtp(n, 2);
      for (Eigen::Index t = 0; t < n; ++t) dtp.row(t) = dt.block(2 * t, p, 2, 1).transpose();
      out.dforce_dproperty.middleCols(k * p, k) = dtp * weights;
    }
  }
  out.history_operator = std::make_shared<PlanarSliderSensitivity>(std::move(slider), weights);
}

void ElasticDryFriction2D::history_step(const MatrixXd& x, const VectorXd& state, double /*dt*/, double /*omega*/,
                                        const std::vector<double>& props, HistoryStep& out) const {
  const CoulombSlider slider = planar_slider(props);
  const VectorXd u = weights * x.row(0).transpose();
  const SliderStep s = slider.step(props[1], u, VectorXd::Zero(2), state);
  const auto du_dforce = s.H.middleCols(slider.x_input(0), 2);
  out.force = weights.transpose() * VectorXd(s.force);
  out.state = s.state;
  out.dforce_dx = weights.transpose() * MatrixXd(du_dforce) * weights;
  out.dforce_dstate = weights.transpose() * MatrixXd(s.G);
  out.dstate_dx = MatrixXd(s.E.middleCols(slider.x_input(0), 2)) * weights;
  out.dstate_dstate = s.A;
  out.diagonal_state = false;
}

MatrixXd ElasticDryFriction2D::periodic_history(const MatrixXd& x, double /*omega*/, const std::vector<double>& props) const {
  CoulombSlider slider = planar_slider(props);
  slider.solve_period(VectorXd::Constant(x.rows(), props[1]), x * weights.transpose(), VectorXd::Zero(2));
  MatrixXd z(x.rows(), 2);
  for (Eigen::Index t = 0; t < x.rows(); ++t) z.row(t) = slider.steps()[static_cast<size_t>(t)].state.transpose();
  return z;
}

}  // namespace hbtrack
