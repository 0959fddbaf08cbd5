#include "hbtrack/runs/case_system.hpp"

#include <stdexcept>

namespace hbtrack::runs {

namespace {
HarmonicBalance build_system(const CaseDefinition& c, const HarmonicBalanceOptions& options) {
  try {
    return HarmonicBalance(c.model, c.elements, c.parameters, options);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
}
}  // namespace

HarmonicBalance make_system(const CaseDefinition& c) {
  if (c.harmonic_balance.adaptive.enabled())
    throw CaseError(c.path + ": harmonic_balance.adaptive: only frc changes H along a branch; this analysis holds one H (leave adaptive " +
                    "out, or --set harmonic_balance.adaptive.max=0)");
  return build_system(c, c.harmonic_balance);
}

HarmonicBalance make_system_at(const CaseDefinition& c, int harmonics) {
  HarmonicBalanceOptions options = c.harmonic_balance;
  options.harmonics = harmonics;
  options.adaptive = AdaptiveHarmonics{};
  return build_system(c, options);
}

}  // namespace hbtrack::runs
