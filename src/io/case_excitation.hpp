#pragma once
// The excitations beside [[forcing]]: [forcing_growth], a forcing that grows with the frequency
// as (omega / omega_ref)^k, and [base_motion], an imposed support motion turned into its
// equivalent forcing in relative coordinates (model/base_motion.hpp).
#include "case_reader.hpp"

namespace hbtrack {

// Both read after [[forcing]], before the model is validated.
void read_forcing_growth(const CaseReader& in, const toml::value& root, CaseDefinition& c);
void read_base_motion(const CaseReader& in, const toml::value& root, CaseDefinition& c);
// After the settings: the base motion's harmonic must be balanced, as a forcing's.
void check_base_motion_within_harmonics(const CaseReader& in, const toml::value& root, const CaseDefinition& c);

}  // namespace hbtrack
