#pragma once
// What `hbtrack study` reads off tracking curves: where a curve crosses a parameter value, the
// extrema of the parameter along it (where limit-point pairs or isolas appear and merge), and the
// parameter values at which validation NFRCs are computed around them.
#include <string>
#include <vector>

namespace hbtrack::cli {

// One tracking curve as `hbtrack track` wrote it (DIR/branch.csv and the min/max special points).
struct TrackingCurve {
  std::string folder;
  std::string parameter;
  std::vector<int> leg;
  std::vector<double> omega, value, first_output;  // first_output: max of the case's first output
  struct Extremum {
    std::string type;  // "min" or "max" of the parameter
    double value = 0, omega = 0, first_output = 0;
  };
  std::vector<Extremum> extrema;
};
TrackingCurve read_tracking_curve_folder(const std::string& dir, const std::string& parameter, const std::string& first_output);

// Omega (and the first output) where the curve crosses `value`, linear between its points.
struct Crossing {
  double omega = 0, first_output = 0;
};
std::vector<Crossing> crossings_at(const TrackingCurve& curve, double value);

// A limit point at (omega, output) already lies on one of `curves` at the parameter's `value`:
// within `relative` of both (linear interpolation between tracking points).
bool lies_on_a_curve(const std::vector<TrackingCurve>& curves, double value, double omega, double output, double relative);

// The parameter values of the validation NFRCs: `offset` (a fraction of the range) on both
// sides of every extremum, inside the range; the range's ends moved in by `offset` when the
// curves have no extremum. Sorted, values closer than offset/2 merged.
std::vector<double> probe_values(const std::vector<TrackingCurve>& curves, double min, double max, double offset);

}  // namespace hbtrack::cli
