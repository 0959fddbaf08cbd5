// frictional_contact with law = "dlft": the penalty law's periodic state applied to the
// prediction lambda / epsilon = x - (gap, 0) - r_lin / epsilon, with k_n = k_t = epsilon.
#include <memory>

#include "hbtrack/elements/frictional_contact.hpp"
#include "penalty_contact_period.hpp"

namespace hbtrack {

namespace {

enum Property { kMu, kEpsilon, kGap };
// Positions of the penalty law's properties in its dforce_dproperty.
enum PenaltyProperty { kNormalStiffness, kTangentialStiffness, kPenaltyMu };

// scale * S: d f / d r_lin = -(1 / epsilon) d f / d x, both through the prediction.
class ScaledSensitivity final : public HistorySensitivity {
 public:
  ScaledSensitivity(std::shared_ptr<const HistorySensitivity> base, double scale) : base_(std::move(base)), scale_(scale) {}
  Eigen::MatrixXd apply(const Eigen::MatrixXd& dx) const override { return scale_ * base_->apply(dx); }
  Eigen::MatrixXd apply_transpose(const Eigen::MatrixXd& w) const override { return scale_ * base_->apply_transpose(w); }

 private:
  std::shared_ptr<const HistorySensitivity> base_;
  double scale_;
};

}  // namespace

void FrictionalContact::evaluate_with_residual(const Eigen::MatrixXd& x, const Eigen::MatrixXd& r, double /*omega*/,
                                               const std::vector<double>& props, ElementResponse& out,
                                               bool want_property_derivatives) const {
  if (law_ != ContactFormulation::dlft) throw std::logic_error("frictional_contact: only law = \"dlft\" reads the linear residual");
  const double epsilon = props[kEpsilon];
  const Eigen::Index n = x.rows();
  Eigen::MatrixXd prediction = x - r / epsilon;
  prediction.col(0).array() -= props[kGap];
  ElementResponse penalty;
  penalty_contact_period(prediction, {epsilon, epsilon, props[kMu], 0.0}, penalty, want_property_derivatives);
  out.force = penalty.force;
  out.dforce_dx.resize(0, 0);
  out.dforce_dv.resize(0, 0);
  out.dforce_domega.resize(0, 0);
  out.history_dforce_dx.resize(0, 0);
  out.history_operator = penalty.history_operator;
  out.residual_operator = std::make_shared<ScaledSensitivity>(penalty.history_operator, -1.0 / epsilon);
  if (!want_property_derivatives) return;
  // epsilon is both penalty stiffnesses and divides r_lin in the prediction; gap moves the
  // normal prediction.
  Eigen::MatrixXd shifts(2 * n, 2);
  shifts.col(0) = Eigen::Map<const Eigen::VectorXd>(r.data(), 2 * n) / (epsilon * epsilon);
  shifts.col(1).head(n).setConstant(-1.0);
  shifts.col(1).tail(n).setZero();
  const Eigen::MatrixXd moved = penalty.history_operator->apply(shifts);
  out.dforce_dproperty.resize(n, 6);
  out.dforce_dproperty.middleCols(2 * kMu, 2) = penalty.dforce_dproperty.middleCols(2 * kPenaltyMu, 2);
  out.dforce_dproperty.middleCols(2 * kEpsilon, 2) =
      penalty.dforce_dproperty.middleCols(2 * kNormalStiffness, 2) + penalty.dforce_dproperty.middleCols(2 * kTangentialStiffness, 2);
  for (int i = 0; i < 2; ++i) {
    out.dforce_dproperty.col(2 * kEpsilon + i) += moved.col(0).segment(i * n, n);
    out.dforce_dproperty.col(2 * kGap + i) = moved.col(1).segment(i * n, n);
  }
}

}  // namespace hbtrack
