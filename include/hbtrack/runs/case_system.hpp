#pragma once
// The harmonic balance system of a case, as every run builds it.
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::runs {

// A model the case reader let through but the system rejects is bad input: a CaseError naming
// the case file. A case with harmonic_balance.adaptive is refused (a CaseError saying so): only
// frc changes H along a branch, every other analysis holds one H.
HarmonicBalance make_system(const CaseDefinition& c);

// The case's system balanced with `harmonics` harmonics, adaptive or not: what an adaptive frc
// builds for each H it visits.
HarmonicBalance make_system_at(const CaseDefinition& c, int harmonics);

}  // namespace hbtrack::runs
