#pragma once
// Special points that the discretisation, not the dynamics, produced: clusters of limit points
// and PD/NS points packed closer than the sampled law can resolve (a C0 contact law sampled at N
// points per period, or a smooth law narrower than one sample, folds the branch into a saw-tooth
// of tiny folds). Listed in summary.json under "warnings" and on stderr, with the fix.
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::runs {

// omega_range: |omega_end - omega_start| of the NFRC; a cluster is at least kClusterSize special
// points with consecutive spacings below kClusterSpacing of the range.
//
// Closeness alone does not make an artefact: NLvib's three-oscillator example (Jenkins elements,
// a unilateral spring) has 4 folds within 1.8e-3 rad/s. So when `recompute` is given (the
// cluster's stretch of branch computed again with more samples and shorter steps: the omegas of
// the limit points it finds there, or nullopt when that run fails), a cluster of limit points is
// reported only when the recomputed stretch has another number of them or one moved by more
// than a tenth of the smallest spacing between them (the pattern then depends on the sampling or
// the step); a cluster that stays is no artefact of either and gets no warning. A cluster
// holding PD or NS points is reported as before.
using ClusterRecomputation = std::function<std::optional<std::vector<double>>(const std::vector<const SpecialPoint*>& cluster)>;
std::vector<std::string> special_point_clusters(const std::vector<SpecialPoint>& points, double omega_range,
                                                const ClusterRecomputation& recompute = {});
// The recomputation's factors on harmonic_balance.samples and, dividing, on the steps.
inline constexpr int kRelocationSamplesFactor = 4;
inline constexpr double kRelocationStepFactor = 4;

// Extremum pairs of a tracking curve (a min next to a max) closer in the parameter than
// kClusterSpacing of its range and in omega than that fraction of the curve's omega span: a
// wiggle the sampled law puts into the curve, not a birth and a merge of branches.
std::vector<std::string> extremum_pairs_below_resolution(const std::vector<FoldExtremum>& extrema, const std::string& parameter,
                                                         double parameter_range, double omega_span);

// PD/NS points that Hill's method alone decided on a law that is not smooth (the model too large
// for the automatic shooting cross-check): Hill's exponent families converge slowly there, and on
// the 32-mass chain example at H = 5 it reports NS points that vanish at H = 10 and that shooting
// does not see. `nonsmooth_element` names such an element ("" when every law is smooth).
// "elements[i] (type)" of the first element whose law is not smooth, "" when none.
std::string first_nonsmooth_element(const CaseDefinition& c);
std::vector<std::string> unconfirmed_hill_bifurcations(const std::vector<SpecialPoint>& points, const std::string& nonsmooth_element,
                                                       int harmonics);

}  // namespace hbtrack::runs
