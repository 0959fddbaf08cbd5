#pragma once
// How much of its range a running computation has covered: the CLI's progress line and the
// Python module's progress callbacks report the same fraction.

namespace hbtrack {

// The part of [start, end] that `value` has covered, 0 to 1 (either direction; 0 for an empty
// range or a value that is not finite).
double covered_fraction(double value, double start, double end);

// How much of its range a run has covered so far, 0 to 1, never lower than before.
class Coverage {
 public:
  // omega from start to end (frc): the furthest value counts, a folding branch that steps back
  // does not lower it.
  static Coverage one_way(double start, double end);
  // A parameter followed from `from` inside [lo, hi] in two legs (track): leg 1 towards lo, leg
  // 2 towards hi, each counting for its share of the range, by the furthest value it reached. A
  // leg that turns back (at a cusp) and leaves the range elsewhere counts as whole once leg 2
  // starts.
  static Coverage two_legs(double lo, double hi, double from);
  // The fraction after this value of the leg (ignored by one_way; values not finite are ignored).
  double add(double value, int leg = 1);
  double fraction() const { return fraction_; }

 private:
  bool two_legs_ = false;
  double start_ = 0, end_ = 0, from_ = 0, fraction_ = 0;
};

}  // namespace hbtrack
