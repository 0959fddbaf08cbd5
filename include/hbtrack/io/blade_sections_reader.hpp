#pragma once
// Reads a blade section table (the format scripts/derive-rotor67-sections.py writes): '#'
// comment lines, one of them `# blade_count = N`, a header row
// `surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m`, then one row per
// point, surfaces numbered from 1 (hub) upwards and points from 1 (leading edge) upwards, in
// order. Bad input throws CaseError "<path>:<line>: <column>: <rule>".
#include <string>

#include "hbtrack/model/blade_sections.hpp"

namespace hbtrack {

BladeSections read_blade_sections(const std::string& path);

}  // namespace hbtrack
