#pragma once
// Continuation of the periodic solution in a named parameter (the forcing amplitude, a friction
// coefficient, a clearance, ...) at a fixed forcing frequency: the harmonic balance residual
// handed to the same arc-length engine as the NFRC, with lambda = the parameter.
#include <functional>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"

namespace hbtrack {

// R(x; p) at fixed omega, lambda = p (the parameter `parameter` of the system's ParameterSet),
// evaluated by its own copy of hbm (the same constant system).
class ParameterProblem final : public ContinuationProblem {
 public:
  ParameterProblem(const HarmonicBalance& hbm, int parameter, double omega, double length_scale, double parameter_scale,
                   double force_scale);
  int size() const override { return hbm_.unknowns(); }
  void evaluate(const Eigen::VectorXd& u, double p, Eigen::VectorXd& r, Eigen::MatrixXd* jacobian, Eigen::VectorXd* r_p) override;
  // Adaptive, as the NFRC's: the current amplitude max|u| floored at length_scale.
  Eigen::VectorXd unknown_scale(const Eigen::VectorXd& u) const override;
  double parameter_scale() const override { return parameter_scale_; }
  double residual_scale() const override { return force_scale_; }
  bool has_corners() const override { return hbm_.has_corners(); }

 private:
  HarmonicBalance hbm_;
  int parameter_;
  double omega_, length_scale_, parameter_scale_, force_scale_;
};

struct ParameterBranchPoint {
  double parameter = 0;
  RecordedPoint recorded;  // recorded.omega is the fixed frequency
};

struct ParameterBranchResult {
  ContinuationResult continuation;  // lambda = the parameter; special points LP (in the parameter), BP, PD, NS
  std::vector<ParameterBranchPoint> points;
  double length_scale = 0;
  int start_newton_iterations = 0;  // of the first solution at the range's start
};

// Called for each accepted point; return false to stop.
using ParameterObserver = std::function<bool(const BranchPoint&, const ParameterBranchPoint&, int)>;

// The branch at frequency `omega` from parameter = start (solved by Newton from the linear
// solution there) towards `end`, with the case's continuation and stability options. hbm's
// other parameter values hold; its own are not changed (the branch is evaluated on copies).
// Throws std::runtime_error when Newton fails at the start.
ParameterBranchResult continue_in_parameter(const HarmonicBalance& hbm, int parameter, double omega, double start, double end,
                                            const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                                            const ParameterObserver& observer = {});

}  // namespace hbtrack
