#pragma once
// The plan of `hbtrack study` (verb_study.cpp): its stages in order, one step of it (a verb run
// into a folder of the study), and the tolerances by which it matches points across steps.
#include <string>
#include <vector>

namespace hbtrack::cli {

// A limit point of a validation NFRC lies on a tracking curve when the located crossing agrees
// to this (relative omega and output): both are Newton solutions to the case's tolerance and the
// NFRC's limit point is located by a secant on its test function.
inline constexpr double kSameLimitPoint = 1e-5;
// Validation NFRCs sit this fraction of the parameter range away from an extremum.
inline constexpr double kProbeOffset = 0.02;
// A BP or PD lies on an earlier switched branch within these (relative omega; outputs' max,
// relative to their largest): a PD band's branch ends within a step of the band's other PD, its
// omega within 1.2e-4 (tests/test_period_doubling.cpp), but its outputs' max up to 0.3 % off on
// the two-dof contact example (the omega/2 harmonic grows as the square root of the distance).
inline constexpr double kSameBranchOmega = 1e-3, kSameBranchOutput = 1e-2;

// The stages of a study, in order, for the lines that say where it is ("stage 3 of 8, tracking").
// A stage with nothing to do for the case (no [study] convergence, no isola) says nothing.
enum Stage { kNominal, kBranches, kTracking, kValidation, kIsolas, kIsolaSimulation, kConvergence, kFigures, kStages };
inline constexpr const char* kStageNames[kStages] = {"nominal NFRC", "branches",         "tracking",    "validation and simulation",
                                                     "isolas",       "isola simulation", "convergence", "figures"};

// One verb run into DIR/folder. A step that may fail keeps going with what it wrote (exit 1: a
// tracking leg or a simulation that stopped early still leaves its points). A step that may be
// refused (exit 2: its verb cannot take the case, e.g. a torus with a hysteretic law) is recorded
// as skipped, with the verb's one-line reason, and the study goes on without it.
struct Step {
  std::string folder;
  std::vector<std::string> args;
  bool must_succeed = false;
  bool may_be_refused = false;
};

}  // namespace hbtrack::cli
