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
  // 2 towards hi, each counting for its share of the range. Within a leg, the part r of the way
  // to its end covered by the furthest value reached, plus the distance T the parameter travelled
  // on the leg: r + (1 - r) T / (T + |hi - lo|). So the share moves on every point of a leg that
  // wanders (turns back at a cusp, the curve following a fold back and forth) and reaches the
  // leg's whole share at its end; a leg that leaves the range at the other end counts as whole
  // once leg 2 starts.
  static Coverage two_legs(double lo, double hi, double from);
  // The fraction after this value of the leg (ignored by one_way; values not finite are ignored).
  double add(double value, int leg = 1);
  double fraction() const { return fraction_; }

 private:
  bool two_legs_ = false;
  double start_ = 0, end_ = 0, from_ = 0, fraction_ = 0;
  // The current leg's: its number, the furthest part of the way reached, the distance travelled
  // and the last value.
  int leg_ = 0;
  double reached_ = 0, travelled_ = 0, last_ = 0;
};

}  // namespace hbtrack
