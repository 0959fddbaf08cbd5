#pragma once
// The period-doubled branch born at a period doubling (PD) of an NFRC. At a PD a Floquet
// multiplier crosses -1: the solution of period T = 2 pi / omega is joined by one of period 2T.
// In the harmonic balance at half the fundamental (subharmonic nu = 2: harmonics k omega / 2)
// the period-T solution is still a solution (its harmonic k sits at 2k, the odd ones zero), and
// the PD is a branch point there: the extended Jacobian gains a second null vector, in the odd
// harmonics, the critical Floquet eigenvector's e^{i omega t / 2} p(t) expanded in omega / 2.
// So the period-doubled branch is switched onto as at any branch point (branch_switching.hpp),
// in the nu = 2 system, and followed as an NFRC of that system (its stability over 2T).
#include "hbtrack/analysis/branch_switching.hpp"

namespace hbtrack {

// The nu = 2 basis of a period-T basis: every harmonic k of `o` as 2k, and the odd multiples
// 1, 3, ..., 2H - 1 of omega / 2 (0..2H when `o` balances 0..H); samples doubled (the same time
// resolution over twice the period). Throws std::invalid_argument when `o` is already subharmonic.
HarmonicBalanceOptions period_doubled_options(const HarmonicBalanceOptions& o);

// x (dofs blocks in the basis `from`, fundamental omega) as the same motion in the basis `to`
// (fundamental omega / nu): harmonic k of `from` is harmonic nu k of `to`, which must list it.
Eigen::VectorXd embed_in_subharmonic_basis(const FourierBasis& from, const FourierBasis& to, int nu, int dofs, const Eigen::VectorXd& x);

// The period-doubled branch from a PD of an NFRC: `doubled` is the nu = 2 system; x_pd and known
// (the NFRC's direction at the PD, [dx; d omega]) in the period-T layout of `basis`. Both legs
// from the first point, within the options' window, their steps at most that point's distance
// from the PD (a PD bubble spans a few of an NFRC's steps). Each stops where it rejoins the
// period-T branch (stop_reason "rejoined": its odd harmonics vanish or change sign; beyond lies
// the same branch shifted by T): `through` at this PD, `away` at the band's other PD.
// `leg_observer` sees the legs' points until they rejoin, as switch_at_branch_point's does.
SwitchedBranch switch_at_period_doubling(HarmonicBalance& doubled, const FourierBasis& basis, const NfrcOptions& options,
                                         const std::vector<OutputDof>& outputs, const Eigen::VectorXd& x_pd, double omega_pd,
                                         const Eigen::VectorXd& known, const RecordedObserver& leg_observer = {});

}  // namespace hbtrack
