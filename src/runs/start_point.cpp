#include "hbtrack/runs/start_point.hpp"

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::runs {

void StartPoint::require_unknowns(int unknowns) const {
  if (x.size() != unknowns)
    throw CaseError(source + ": holds " + std::to_string(x.size()) + " unknowns, the case's harmonic balance has " +
                    std::to_string(unknowns) + " (a result of another case?)");
}

}  // namespace hbtrack::runs
