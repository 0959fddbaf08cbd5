#pragma once
// [study]: what `hbtrack study` varies and computes beside the nominal NFRC (tracked parameters,
// backbones, switched branches, tori, the convergence check; docs/case-file.md).
#include "case_reader.hpp"

namespace hbtrack {

// After [harmonic_balance] (the torus' samples are checked against its harmonics) and the
// parameters (a tracked parameter must be one).
void read_study(const CaseReader& in, const toml::value& root, CaseDefinition& c);

}  // namespace hbtrack
