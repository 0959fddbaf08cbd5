#pragma once
// The harmonic balance system of a case, as every run builds it.
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::runs {

// A model the case reader let through but the system rejects is bad input: a CaseError naming
// the case file.
HarmonicBalance make_system(const CaseDefinition& c);

}  // namespace hbtrack::runs
