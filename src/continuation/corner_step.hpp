#pragma once
// The step over a corner of a branch whose residual is only piecewise smooth
// (ContinuationProblem::has_corners: a sampled stick-slip or contact law, piecewise affine in u
// with a piece per pattern of stick, slip and contact samples). Private to src/continuation.
//
// Where one sample changes pattern the branch turns by a finite angle. When it turns by more than
// 90 degrees (in the scaled coordinates; measured on the DLFT example: 100 and 172 degrees), no
// point beyond the corner lies on the pseudo-arclength plane t.(y - x) = ds ahead of x: the
// corrector has nothing to converge to and Newton alternates between the two pieces' affine
// solutions, each lying in the other piece, at every step size. The corner step instead
//  1. takes the residual at the prediction x + ds t, in the next piece, where it grows linearly
//     along t from zero at the corner: R(x + s t) = (s - delta) R_s. Fitting that line locates
//     the corner at delta (refused when the fit is poor: more than one corner in reach);
//  2. corrects that point onto the branch (it is one: the pieces meet there);
//  3. leaves it along the next piece's tangent, the null vector of its Jacobian [R_u R_lambda],
//     oriented so that sign det [R_u R_lambda; t^T] is that of the branch before the corner:
//     along a branch crossing a corner transversally that sign does not change (the orientation
//     of a piecewise linear curve, Allgower & Georg, Numerical Continuation Methods, ch. 12),
//     and it is how the branch goes on whether it turns by 10 or 170 degrees.
#include "scaled_problem.hpp"

namespace hbtrack::continuation_detail {

// From the point x with unit tangent t (scaled) and sign det_sign of its bordered Jacobian, a
// step of length ds: true when a corner was found within it, with the corner on the branch in
// `corner`, the tangent leaving it in `outgoing` (and the determinant of its bordered matrix) and
// the Newton iterations spent added to `iterations`.
bool step_to_corner(Scaled& s, const VectorXd& x, const VectorXd& t, int det_sign, double ds, const ContinuationOptions& options,
                    VectorXd& corner, Tangent& outgoing, int& iterations);

}  // namespace hbtrack::continuation_detail
