#pragma once
// The [[elements]] section of a case file: type, dofs, properties (numbers or parameter
// bindings) and their physical ranges, one line per error.
#include "case_reader.hpp"

namespace hbtrack {

void read_elements(const CaseReader& in, const toml::value& root, CaseDefinition& c);

}  // namespace hbtrack
