#include "hbtrack/runs/sticking_slider_warnings.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "hbtrack/timeint/initial_state.hpp"

namespace hbtrack::runs {

namespace {

struct OffRestStick {
  int points = 0;
  double omega_min = std::numeric_limits<double>::infinity(), omega_max = -std::numeric_limits<double>::infinity();
  double largest_offset = 0;
};

// The stuck slider's distance from rest, or a negative value when the slider moves during the
// period or sits at rest to within kOffRestFraction of the motion's range.
double off_rest_offset(const NonlinearElement& element, const Eigen::MatrixXd& local, double omega, const std::vector<double>& props) {
  const Eigen::MatrixXd slider = element.periodic_history(local, omega, props);
  const double range = (local.colwise().maxCoeff() - local.colwise().minCoeff()).maxCoeff();
  const double scale = std::max({range, slider.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min()});
  // A stuck slider's position is one value over the period, to rounding.
  const double moves = (slider.colwise().maxCoeff() - slider.colwise().minCoeff()).maxCoeff();
  if (moves > 1e-12 * scale) return -1;
  const double offset = slider.row(0).norm();
  return offset > kOffRestFraction * range ? offset : -1;
}

}  // namespace

std::vector<std::string> sticking_slider_warnings(HarmonicBalance& hbm, const std::vector<BranchPoint>& points) {
  std::vector<std::string> warnings;
  // A subharmonic branch's period holds several forcing periods; not sampled here.
  if (hbm.subharmonic() != 1) return warnings;
  const ElementList& elements = hbm.elements();
  std::vector<size_t> free_sliders;
  for (size_t e = 0; e < elements.size(); ++e)
    if (elements[e]->stuck_slider_position_is_free()) free_sliders.push_back(e);
  if (free_sliders.empty()) return warnings;
  std::vector<std::vector<double>> props;
  for (size_t e : free_sliders) props.push_back(elements[e]->property_values(hbm.parameter_values()));
  std::vector<OffRestStick> found(free_sliders.size());
  const int dofs = hbm.model().dofs(), harmonics = hbm.basis().harmonics(), samples = hbm.basis().samples();
  for (const BranchPoint& p : points) {
    // Every dof's motion over the period once per point, each slider's columns taken from it.
    const Eigen::MatrixXd period = period_samples(hbm.expand(p.u, p.lambda), dofs, harmonics, samples);
    for (size_t k = 0; k < free_sliders.size(); ++k) {
      const NonlinearElement& element = *elements[free_sliders[k]];
      Eigen::MatrixXd local(period.rows(), element.local_dofs());
      for (int i = 0; i < element.local_dofs(); ++i) local.col(i) = period.col(element.dofs[static_cast<size_t>(i)]);
      const double offset = off_rest_offset(element, local, p.lambda, props[k]);
      if (offset < 0) continue;
      OffRestStick& f = found[k];
      ++f.points;
      f.omega_min = std::min(f.omega_min, p.lambda);
      f.omega_max = std::max(f.omega_max, p.lambda);
      f.largest_offset = std::max(f.largest_offset, offset);
    }
  }
  for (size_t k = 0; k < free_sliders.size(); ++k) {
    const OffRestStick& f = found[k];
    if (f.points == 0) continue;
    char where[160];
    std::snprintf(where, sizeof where, "with its slider off rest (by up to %.3g) at %d points, omega %.6g to %.6g", f.largest_offset,
                  f.points, f.omega_min, f.omega_max);
    warnings.push_back("elements[" + std::to_string(free_sliders[k]) + "] (" + elements[free_sliders[k]]->type() +
                       ") sticks for the whole period " + where +
                       ": the periodic problem leaves a stuck slider anywhere it stays stuck; hbtrack takes the middle of that band, "
                       "a tool that starts it from rest (NLvib) or a time integration can settle on another orbit there "
                       "(docs/elements.md)");
  }
  return warnings;
}

}  // namespace hbtrack::runs
