#pragma once
// A Jenkins slider in d = 1 or 2 tangential directions whose slip limit mu N follows a varying
// normal load N >= 0, free when N = 0: the tangential law of frictional_contact (d = 1) and of
// tip_contact with friction = "stick_slip" (d = 2, a Coulomb disc).
//
// State: the slider position zeta (d), in the frame of the tangential displacements x. The
// counterface may move on its own (a rotating casing): a stuck slider is carried by -drift per
// step. One step, with zeta' = zeta_prev - drift and the trial force T* = kt (x - zeta'):
//   N = 0            separated: T = 0, zeta = x;
//   |T*| <= mu N     stick:     T = T*, zeta = zeta';
//   otherwise        slip:      T = mu N T*/|T*|, zeta = x - T/kt.
// In one direction a slip or a separation erases the memory; in two the force keeps the
// direction of the trial, so the past fades geometrically instead (by mu N / |T*| per slip
// step across the sliding direction).
//
// Linearisation of a step with respect to the previous state and the inputs
// v = [N, x (d), drift (d), mu, kt] (q = 3 + 2d of them):
//   dT = G dzeta_prev + H dv,   dzeta = A dzeta_prev + E dv.
// Over a period these define a linear periodic recurrence; its response to input perturbations
// (and the transposed one) is what the harmonic balance needs: periodic_response().
#include <Eigen/Dense>
#include <vector>

#include "hbtrack/elements/nonlinear_element.hpp"
#include "stick_centre.hpp"

namespace hbtrack {

enum class SlideMode { stick, slip, separated };

// Sizes bounded by d <= 2, q <= 7: stored in place, so that the N steps of a period (one per
// sample, at every residual evaluation) allocate nothing.
using SliderVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2, 1>;
using SliderSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 2, 2>;
using SliderInputs = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 2, 7>;

struct SliderStep {
  SlideMode mode = SlideMode::stick;
  SliderVector force, state;  // T, zeta after the step (d each)
  SliderSquare G, A;          // d x d
  SliderInputs H, E;          // d x q
};

class CoulombSlider {
 public:
  CoulombSlider(int directions, double tangential_stiffness, double mu);
  int directions() const { return d_; }
  int inputs() const { return 3 + 2 * d_; }  // q
  // Input positions within v.
  int normal_input() const { return 0; }
  int x_input(int i) const { return 1 + i; }
  int drift_input(int i) const { return 1 + d_ + i; }
  int mu_input() const { return 1 + 2 * d_; }
  int stiffness_input() const { return 2 + 2 * d_; }

  SliderStep step(double normal, const SliderVector& x, const SliderVector& drift, const SliderVector& previous) const;

  // The periodic steady state over N samples (normal: N, x: N x d, drift per sample: d). When
  // the slider can stick all period (always in contact, no drift, some position within
  // mu N(t) / k_t of every x(t)), the periodic problem leaves it anywhere it sticks: it is put
  // at the position of largest margin (stick_centre.hpp, continuous with the slipping state),
  // and `anchored` says so. Otherwise passes of the period are repeated, with Newton on the
  // state at the period's start (the pass is affine in it at a fixed stick-slip pattern),
  // until that state repeats to round-off. steps() holds the per-sample steps of the final pass.
  void solve_period(const Eigen::VectorXd& normal, const Eigen::MatrixXd& x, const Eigen::VectorXd& drift);
  const std::vector<SliderStep>& steps() const { return steps_; }
  bool anchored() const { return anchored_; }

  // Response of T to perturbations of the inputs over the period: dv holds one column per
  // case, rows t * q + input; returns dT with rows t * d + direction (an anchored slider moves
  // with the extremes of x). The transposed map takes weights on dT to weights on dv.
  Eigen::MatrixXd periodic_response(const Eigen::MatrixXd& dv) const;
  Eigen::MatrixXd periodic_response_transpose(const Eigen::MatrixXd& dt) const;

 private:
  // Period map of the state linearisation: A_(N-1) ... A_0.
  SliderSquare period_map() const;

  int d_;
  double kt_, mu_;
  // The anchored position's dependence on the perturbation dv (rows t * q + input).
  Eigen::MatrixXd centre_response(const Eigen::MatrixXd& dv) const;

  std::vector<SliderStep> steps_;
  Eigen::VectorXd normal_;
  bool anchored_ = false;
  StickCentre centre_;
};

// A contact node [normal, tangential...] (normal dof 0, tangential dofs 1..d) whose normal force
// N(x_n) is pointwise and whose tangential force is a slider's: its d f / d x as the operator the
// AFT applies, and its time step.
class ContactSliderSensitivity final : public HistorySensitivity {
 public:
  // dnormal_dx: dN/dx_n at each sample.
  ContactSliderSensitivity(CoulombSlider slider, Eigen::VectorXd dnormal_dx)
      : slider_(std::move(slider)), dnormal_dx_(std::move(dnormal_dx)) {}
  Eigen::MatrixXd apply(const Eigen::MatrixXd& dx) const override;
  Eigen::MatrixXd apply_transpose(const Eigen::MatrixXd& w) const override;

 private:
  CoulombSlider slider_;
  Eigen::VectorXd dnormal_dx_;
};

// The return mapping of such a node over one step (x: 1 x (1 + d), the normal force and its
// derivative given), in NonlinearElement::history_step's terms.
void contact_slider_step(const CoulombSlider& slider, double normal, double dnormal_dx, const Eigen::MatrixXd& x,
                         const Eigen::VectorXd& drift, const Eigen::VectorXd& state, HistoryStep& out);

}  // namespace hbtrack
