#include "hbtrack/runs/case_system.hpp"

#include <stdexcept>

namespace hbtrack::runs {

HarmonicBalance make_system(const CaseDefinition& c) {
  try {
    return HarmonicBalance(c.model, c.elements, c.parameters, c.harmonic_balance);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
}

}  // namespace hbtrack::runs
