#pragma once
// Branch switching at a simple branch point (BP) of an NFRC: at the BP the extended Jacobian
// [R_x R_omega] has a two-dimensional null space holding the tangents of both branches. The
// known branch's tangent is removed from it; what is left is the new branch's tangent (exact
// for the symmetry-breaking pitchforks of symmetric structures, where the bifurcating branch
// leaves along the antisymmetric null vector; a transcritical BP would need the algebraic
// bifurcation equation). A step along it, corrected on the hyperplane normal to it, gives a
// point of the new branch, which is continued both ways.
#include "hbtrack/analysis/nfrc.hpp"

namespace hbtrack {

struct SwitchedBranch {
  Eigen::VectorXd tangent;  // the new branch's unit tangent at the BP, scaled ([x ./ s; omega / s_omega])
  Eigen::VectorXd x1;       // the first point on the new branch
  double omega1 = 0;
  NfrcResult away;     // from that point, away from the BP
  NfrcResult through;  // from that point, back through the BP to the other side (empty: one leg)
};

// x_bp, omega_bp: the BP; known: the known branch's direction there ([dx; d omega], e.g. the
// secant between its neighbours on the NFRC). The scales and the window are those of the NFRC
// (options). The first point is sought at twice the options' step from the BP, and closer (by
// halves, to 1/64 of it) when the corrector fails there (a branch that exists only over a
// narrow range). `both_ways` false: only the leg away from the BP, which stops when it closes
// on itself. `local_steps`: the legs' steps at most that first distance (a branch whose whole
// extent is a few of the case's steps, as a period-doubling bubble, would be stepped over onto
// the branch it meets). `leg_observer` sees both legs' points (index 0 starts a leg; false stops
// that leg: stop_reason "interrupted"). Throws std::runtime_error when no point of a new branch
// is found.
SwitchedBranch switch_at_branch_point(HarmonicBalance& hbm, const NfrcOptions& options, const std::vector<OutputDof>& outputs,
                                      const Eigen::VectorXd& x_bp, double omega_bp, const Eigen::VectorXd& known, bool both_ways = true,
                                      bool local_steps = false, const RecordedObserver& leg_observer = {});

}  // namespace hbtrack
