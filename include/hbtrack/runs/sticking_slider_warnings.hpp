#pragma once
// Branch points where a slider sticks for the whole period away from its rest position. The
// periodic problem does not fix such a slider: any position that keeps it stuck gives a periodic
// solution, and hbtrack reports the one in the middle of that band (docs/elements.md). NLvib's
// sliders start from rest and keep where the first slip left them; a time integration keeps
// where its transient left them. Where the band is off the rest position those choices are
// different orbits, so tools and time integration part there (NLvib's three-oscillator example:
// docs/elements.md). Listed in summary.json under "warnings".
#include <string>
#include <vector>

#include "hbtrack/continuation/continuation.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack::runs {

// A slider counts as off its rest position when its stuck position is further from 0 than
// kOffRestFraction of its displacement's range over the period (closer, the choices differ by
// less than that share of the motion).
inline constexpr double kOffRestFraction = 1e-3;

// One warning per element with stuck_slider_position_is_free() that sticks off rest at some of
// `points` (u: the unknowns, lambda: omega).
std::vector<std::string> sticking_slider_warnings(HarmonicBalance& hbm, const std::vector<BranchPoint>& points);

}  // namespace hbtrack::runs
