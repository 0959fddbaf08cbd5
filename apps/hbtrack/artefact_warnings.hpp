#pragma once
// Special points that the discretisation, not the dynamics, produced: clusters of limit points
// and PD/NS points packed closer than the sampled law can resolve (a C0 contact law sampled at N
// points per period, or a smooth law narrower than one sample, folds the branch into a saw-tooth
// of tiny folds). Listed in summary.json under "warnings" and on stderr, with the fix.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack::cli {

// omega_range: |omega_end - omega_start| of the NFRC; a cluster is at least kClusterSize special
// points with consecutive spacings below kClusterSpacing of the range.
std::vector<std::string> special_point_clusters(const std::vector<SpecialPoint>& points, double omega_range);

}  // namespace hbtrack::cli
