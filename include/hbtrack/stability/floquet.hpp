#pragma once
// Floquet exponents and multipliers of a periodic solution of period T = 2 pi / omega: the 2n
// exponents l (n dofs) with multipliers mu = exp(l T). The solution is stable when every
// multiplier lies inside the unit circle (every exponent has a negative real part).
#include <Eigen/Dense>
#include <optional>

#include "hbtrack/util/choices.hpp"
#include "hbtrack/util/special_point_type.hpp"

namespace hbtrack {

struct FloquetResult {
  StabilityMethod method = StabilityMethod::hill;  // the one that computed it (never none)
  Eigen::VectorXcd exponents;                      // 2n, sorted by increasing |Im l| (Hill) or from log(mu) / T
  Eigen::VectorXcd multipliers;
  double max_real = 0;  // largest real part of the exponents
  bool stable = true;
  // Hill: the largest distance (in harmonics) of a kept eigenvector's energy centroid from the
  // centre; near 0 when each kept exponent is the well-resolved member of its family.
  double centroid_spread = 0;
};

// Fills multipliers, max_real and stable from exponents. `tolerance` on max_real (in 1/s):
// a multiplier on the unit circle to round-off counts as stable.
void finish_floquet(FloquetResult& r, double omega, double tolerance);

// Test functions of the multipliers whose sign changes bracket bifurcations, built from the
// multipliers near the unit circle only: (-1)^(number outside) times the distance of the
// nearest one to the circle, over real negative multipliers (period doubling: one crosses -1)
// or complex ones (Neimark-Sacker: a pair crosses; a real pair colliding outside the circle
// also flips it, hence the confirmation below).
double period_doubling_test(const Eigen::VectorXcd& multipliers);
double neimark_sacker_test(const Eigen::VectorXcd& multipliers);
// Whether a multiplier sits where a bifurcation of `type` puts it: PD a real one at -1, NS a
// complex one on the unit circle, LP a real one at +1, within `tolerance`.
// The type of the bifurcation whose multiplier sits on the unit circle (within `tolerance`), read
// from the multipliers rather than from which test function flipped: PD a real multiplier at -1,
// NS a complex pair (Hill's split of a real pair near -1, |Im mu| <= `real_tolerance` |mu|,
// counts as real), LP a real one at +1, nullopt none.
std::optional<SpecialPointType> crossing_type(const Eigen::VectorXcd& multipliers, double tolerance, double real_tolerance);
bool has_multiplier_on_unit_circle(const Eigen::VectorXcd& multipliers, SpecialPointType type, double tolerance);

}  // namespace hbtrack
