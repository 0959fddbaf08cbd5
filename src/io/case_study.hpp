#pragma once
// [study]: what `hbtrack study` varies and computes beside the nominal NFRC (tracked parameters,
// backbones, switched branches, the convergence check; docs/case-file.md).
#include "case_reader.hpp"

namespace hbtrack {

// After the parameters (a tracked parameter must be one).
void read_study(const CaseReader& in, const toml::value& root, CaseDefinition& c);

}  // namespace hbtrack
