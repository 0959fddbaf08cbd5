#pragma once
// Defining systems of a limit point (fold in omega) of the harmonic balance solutions, as
// continuation problems in a second parameter gamma (lambda = gamma): the continuation then
// follows the limit point as gamma changes (paper section 3; method notes section 6).
//
// - ExtendedFoldSystem, the paper's (eqs 25-45): unknowns [x, phi, omega], equations
//   R = 0, R_x phi = 0, phi^T phi = 1; 2q + 1 unknowns.
// - BorderedFoldSystem, minimally augmented (Govaerts): unknowns [x, omega], equations R = 0,
//   g = 0 with g from [[R_x, b], [c^T, 0]] [v; g] = [0; 1]; q + 1 unknowns. Its borders b, c
//   follow the left and right null vectors from point to point.
//
// Second derivatives of R come from one forward difference along the null vector (eqs 30-43:
// eps = eta (|x| / |d| + eta), eta = 1e-6): d/de R_x(x + e d) is both (R_x d)_x and, by the
// symmetry of second derivatives, the gradient of w^T R_x d (the bordered system differences
// only that gradient, a transposed product cheaper than a Jacobian). They only shape Newton's
// Jacobian; the residual (the fold condition itself) is exact. The amplitude enters R
// linearly and independently of x, so its mixed derivative is exactly zero and skipped.
#include <Eigen/Dense>
#include <limits>
#include <string>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/util/dense_lu.hpp"

namespace hbtrack {

// Units of the unknowns and equations, so that both systems weigh their parts alike.
struct FoldScales {
  double length = 1;     // displacement unit (floor when adaptive)
  double omega = 1;      // frequency unit of the arc length
  double force = 1;      // residual unit: convergence is ||R||_inf <= tolerance * force
  double parameter = 1;  // unit of gamma in the arc length
};

class FoldSystem : public ContinuationProblem {
 public:
  // The system evaluates its own copy of hbm (same constant system), with gamma set per point.
  FoldSystem(const HarmonicBalance& hbm, int parameter, const FoldScales& scales);
  virtual std::string method() const = 0;
  // Harmonics and frequency of the unknown vector u.
  Eigen::VectorXd harmonics(const Eigen::VectorXd& u) const { return u.head(q_); }
  double omega(const Eigen::VectorXd& u) const { return u(u.size() - 1); }
  // Unknowns at an approximate fold (x, omega) whose R_x has right and left null vectors
  // `right` and `left` (unit).
  virtual Eigen::VectorXd start(const Eigen::VectorXd& x, double omega, const Eigen::VectorXd& right, const Eigen::VectorXd& left) = 0;
  // Unknowns at an approximate singular point (x, omega) of the parameter value gamma: start()
  // with the null vectors of R_x there (the Hill-pencil systems find their own).
  virtual Eigen::VectorXd start_at(const Eigen::VectorXd& x, double omega, double gamma);
  // The frequency |Im lambda| of the exponent crossing the imaginary axis (NS, PD); NaN for a fold.
  virtual double critical_frequency(const Eigen::VectorXd& /*u*/) const { return std::numeric_limits<double>::quiet_NaN(); }
  // After each accepted point (the bordered system renews its borders there).
  virtual void accepted(const Eigen::VectorXd& /*u*/, double /*gamma*/) {}
  // What the system carries from point to point besides the unknowns (the bordered system's
  // borders), for a checkpoint; restore_borders puts it back before a resumed continuation.
  virtual std::vector<Eigen::VectorXd> borders() const { return {}; }
  virtual void restore_borders(const std::vector<Eigen::VectorXd>& /*borders*/) {}
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override;
  double parameter_scale() const override { return scales_.parameter; }
  double residual_scale() const override { return scales_.force; }

 protected:
  // R, and with `derivatives` R_x, R_omega, R_gamma, at (x, omega) with gamma set.
  struct Evaluation {
    Eigen::VectorXd r, r_omega, r_gamma;
    Eigen::MatrixXd j;
  };
  void evaluate_hbm(const Eigen::VectorXd& x, double omega, double gamma, bool derivatives, Evaluation& e);
  // d/de at e = 0 of R_x, R_omega and R_gamma at x + e d (forward difference from `base`),
  // into `out`.
  struct SecondDerivatives {
    Eigen::MatrixXd j;
    Eigen::VectorXd r_omega, r_gamma;
  };
  void along(const Eigen::VectorXd& x, double omega, double gamma, const Eigen::VectorXd& d, const Evaluation& base,
             SecondDerivatives& out);
  // (R_gamma(xs) - R_gamma(x)) / eps with R_gamma(x) in `base`; zero for the amplitude.
  void parameter_derivative_change(const Eigen::VectorXd& xs, double omega, double eps, const Evaluation& base, Eigen::VectorXd& out);
  // The same derivatives seen through a left vector w, all the bordered system needs:
  // d/de of R_x(x + e d)^T w, w . R_omega and w . R_gamma. Only the nonlinear forces' parts of
  // R_x and R_omega are differenced, and their products with w are formed in the time domain,
  // so no q x q Jacobian is assembled at x + e d.
  struct LeftSecondDerivatives {
    Eigen::VectorXd jacobian_transpose_w;
    double omega = 0, gamma = 0;
  };
  void along_left(const Eigen::VectorXd& x, double omega, double gamma, const Eigen::VectorXd& d, const Eigen::VectorXd& w,
                  const Evaluation& base, LeftSecondDerivatives& out);
  // Workspaces reused by every evaluation (q x q matrices: no allocation per Newton iteration).
  Evaluation base_, shifted_;
  SecondDerivatives second_;
  LeftSecondDerivatives left_second_;
  Eigen::VectorXd base_product_;  // J_nl(x)^T w in along_left

  HarmonicBalance hbm_;
  int parameter_;
  bool linear_in_parameter_;  // the amplitude: R_gamma does not depend on x
  FoldScales scales_;
  int q_;
};

class ExtendedFoldSystem final : public FoldSystem {
 public:
  using FoldSystem::FoldSystem;
  std::string method() const override { return "extended"; }
  int size() const override { return 2 * q_ + 1; }
  void evaluate(const Eigen::VectorXd& u, double gamma, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_gamma) override;
  Eigen::VectorXd start(const Eigen::VectorXd& x, double omega, const Eigen::VectorXd& right, const Eigen::VectorXd& left) override;
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override;
};

class BorderedFoldSystem final : public FoldSystem {
 public:
  using FoldSystem::FoldSystem;
  std::string method() const override { return "bordered"; }
  int size() const override { return q_ + 1; }
  void evaluate(const Eigen::VectorXd& u, double gamma, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_gamma) override;
  Eigen::VectorXd start(const Eigen::VectorXd& x, double omega, const Eigen::VectorXd& right, const Eigen::VectorXd& left) override;
  void accepted(const Eigen::VectorXd& u, double gamma) override;
  std::vector<Eigen::VectorXd> borders() const override { return {b_, c_}; }
  void restore_borders(const std::vector<Eigen::VectorXd>& borders) override;
  // LUs of the bordered matrix so far (a residual from kept factors needs none).
  int border_factorizations() const { return border_factorizations_; }

 private:
  // Solves the bordered systems at the current Jacobian: v (right), w (left), g. With
  // `refine`, by iterative refinement from the factors of the last bordered matrix factored
  // (a residual without the Jacobian is a chord iteration, near the point of the corrector's
  // Newton step), and by a fresh LU when the refinement does not reach working accuracy.
  void null_vectors(const Eigen::MatrixXd& j, bool left, bool refine = false);
  bool refine_right_null_vector();
  Eigen::MatrixXd border_matrix_;  // [[R_x, b], [c^T, 0]], a kept workspace
  DenseLU border_lu_;              // factors of the last bordered matrix factored
  int border_factorizations_ = 0;
  Eigen::VectorXd solution_, correction_;  // refinement workspaces
  Eigen::VectorXd b_, c_;                  // borders: left and right null vectors of the last accepted point
  Eigen::VectorXd v_, w_;                  // of the last evaluation
  double g_ = 0;
  Eigen::VectorXd last_u_;  // where v_ and w_ were computed (w_ only if has_left_)
  double last_gamma_ = 0;
  bool has_left_ = false;
};

// Right and left null vectors (unit) of a nearly singular square matrix, by inverse iteration.
void approximate_null_vectors(const Eigen::MatrixXd& j, Eigen::VectorXd& right, Eigen::VectorXd& left);

}  // namespace hbtrack
