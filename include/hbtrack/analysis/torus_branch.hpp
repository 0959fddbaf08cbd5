#pragma once
// The quasi-periodic response born at a Neimark-Sacker point of an NFRC, continued in omega: a
// branch of tori (torus_system.hpp). The start: the NS point refined on its defining system at
// fixed parameters (critical_exponent_system.hpp: the periodic solution x, omega_NS and the NS
// frequency nu), Hill's critical eigenvector v there (the perturbation Re(e^{i nu t} v(omega t)):
// its (k1, +-1) content), the torus x(theta1) + eps Re(e^{i theta2} v(theta1)) projected on the
// torus basis, omega2 = nu. The pair (k1, +-1) and the dof where v is largest fix the phase (its
// sine coefficient is zero, v turned so that it is) and measure the torus' size (its cosine
// coefficient). A first torus is solved with that size fixed at eps and omega free (on which side
// of omega_NS the torus lies is then known), then the branch is continued in omega by the
// arc-length engine within [omega_min, omega_max] until it leaves that range or its size changes
// sign: the torus has shrunk back onto the periodic branch, at another NS point
// (StopReason::reached_ns_point).
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "hbtrack/analysis/torus_system.hpp"
#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/hbm/recorded_outputs.hpp"
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack {

struct TorusOptions {
  int h1 = 0, h2 = 4;  // harmonics in theta1 (0: the case's H) and in theta2
  int n1 = 0, n2 = 0;  // grid (0: the case's samples for N1, the same rule for N2)
  double omega_min = 0, omega_max = 0;
  // The first torus' size eps, as a fraction of the periodic amplitude of the phase dof at the NS point.
  double start_fraction = 0.02;
  ContinuationOptions continuation;
};

// Extremes of one output over the torus (the grid's extreme sample refined by Newton in the two phases).
struct TorusEnvelope {
  double max = 0, min = 0;
};

struct TorusPoint {
  double omega = 0, omega2 = 0;
  double size = 0;                      // the phase pair's cosine coefficient (0 at the NS point)
  Eigen::VectorXd u;                    // [X, omega2] on the retained dofs (row 0: the periodic solution at the NS point, omega2 = nu)
  std::vector<TorusEnvelope> envelope;  // one per output
  int newton_iterations = 0;
};

struct TorusBranchResult {
  double omega_ns = 0, nu = 0;               // the refined NS point and its frequency
  int phase_pair = 0, phase_dof = 0;         // what the phase condition fixes (phase_dof: a model dof)
  int k1 = 0, k2 = 0;                        // that pair
  std::vector<TorusPoint> points;            // the NS point (row 0), then the tori
  std::vector<SpecialPoint> special_points;  // the engine's (LP: a fold of the torus branch in omega)
  ContinuationSummary summary;
  StopReason stop_reason = StopReason::running;
  bool success() const;
};

using TorusObserver = std::function<bool(const TorusPoint&, int)>;

// The dofs a torus keeps as unknowns: every element's and every output's (sorted); the others are
// linear and condensed out (torus_linear_part.hpp).
std::vector<int> torus_retained_dofs(const HarmonicBalance& hbm, const std::vector<OutputDof>& outputs);

// Resolved grid sizes of `options` for `hbm` (0 replaced by their defaults).
TorusOptions resolved_torus_options(const HarmonicBalance& hbm, TorusOptions options);

// Throws std::runtime_error when the NS point cannot be refined or the first torus not solved;
// std::invalid_argument when the case has something the torus cannot take (TorusSystem).
TorusBranchResult torus_branch(const HarmonicBalance& hbm, const Eigen::VectorXd& x_ns, double omega_ns, const FoldScales& scales,
                               const TorusOptions& options, const std::vector<OutputDof>& outputs, const TorusObserver& observer = {});

}  // namespace hbtrack
