#include "hbtrack/util/coverage.hpp"

#include <algorithm>
#include <cmath>

namespace hbtrack {

double covered_fraction(double value, double start, double end) {
  const double span = end - start;
  if (span == 0 || !std::isfinite(value)) return 0;
  return std::clamp((value - start) / span, 0.0, 1.0);
}

Coverage Coverage::one_way(double start, double end) {
  Coverage c;
  c.start_ = start;
  c.end_ = end;
  return c;
}

Coverage Coverage::two_legs(double lo, double hi, double from) {
  Coverage c = one_way(lo, hi);
  c.two_legs_ = true;
  c.from_ = from;
  return c;
}

double Coverage::add(double value, int leg) {
  if (!std::isfinite(value)) return fraction_;
  if (!two_legs_) return fraction_ = std::max(fraction_, covered_fraction(value, start_, end_));
  const int this_leg = leg <= 1 ? 1 : 2;
  if (this_leg != leg_) {  // every leg starts at the limit point
    leg_ = this_leg;
    reached_ = travelled_ = 0;
    last_ = from_;
  }
  travelled_ += std::abs(value - last_);
  last_ = value;
  reached_ = std::max(reached_, covered_fraction(value, from_, leg_ == 1 ? start_ : end_));
  const double width = std::abs(end_ - start_);
  const double way = width > 0 ? reached_ + (1 - reached_) * travelled_ / (travelled_ + width) : reached_;
  const double first = covered_fraction(from_, start_, end_);  // leg 1's share: [lo, from]
  const double part = leg_ == 1 ? first * way : first + (1 - first) * way;
  return fraction_ = std::max(fraction_, part);
}

}  // namespace hbtrack
