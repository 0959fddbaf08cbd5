#pragma once
// What a case's reduced model knows of the full model it was reduced from, for `hbtrack modes`:
// when the case's [model] dofs file is the summary.json of `hbtrack reduce`, the full model's
// frequencies that reduce compared with its own, and the mode names (1B, 2B, 1T) that
// `make-blade` gave them, from reduce's full_model.mode_types or from a make-blade summary kept
// beside it as full_model_summary.json (as data/rotor67/ ships it).
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::cli {

struct FullModelModes {
  std::string reduce_summary;       // the reduce summary.json the case reads, "" for another model
  std::vector<double> frequencies;  // the full model's lowest, rad/s
  std::vector<std::string> names;   // "1B", "2B", "1T", ... ("?" unnamed); empty when unknown
};

// Empty (reduce_summary "") when the case's model is not a reduced one; never throws (the case
// was read already: what is missing here is only not shown).
FullModelModes full_model_modes(const CaseDefinition& c);

}  // namespace hbtrack::cli
