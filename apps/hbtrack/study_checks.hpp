#pragma once
// The study's verdict: what must hold for `hbtrack study` to say "completed".
#include <nlohmann/json.hpp>

namespace hbtrack::cli {

// One sentence per failed check of a study summary, empty when it may say "completed": every
// step exited 0 (a time integration that ran but did not reach a periodic state within the
// asked periods is a finding of the comparison, not a failure), every validation NFRC reached
// the end of its range, and every limit point of every validation NFRC lies on a tracking curve.
nlohmann::json failed_checks(const nlohmann::json& summary);

}  // namespace hbtrack::cli
