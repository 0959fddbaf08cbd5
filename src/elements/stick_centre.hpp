#pragma once
// Where to put a slider that sticks over the whole period. It sticks at z when
// |x(t) - z| <= r(t) at every sample (r = mu N / k_t), and the periodic problem does not say
// which such z the transient left it at. The choice that is continuous with the slipping state
// as the motion grows is the point of largest margin,
//   z* = argmax_z min_t (r(t) - |x(t) - z|),
// since at the onset of slip the set shrinks to that one point. In one direction it is the
// middle of [max_t (x - r), min_t (x + r)] (the midrange of x when r is constant, as
// elastic_dry_friction has it); in two, the centre of the smallest circle "enclosing" the
// circles of radii -r(t) (the additively weighted one-centre problem), found by Welzl's
// randomised incremental algorithm, expected O(N). The margin is negative when no z sticks.
#include <Eigen/Dense>
#include <vector>

namespace hbtrack {

struct StickCentre {
  Eigen::VectorXd z;  // d
  double margin = 0;  // min_t (r(t) - |x(t) - z|)
  // The samples that fix z (1 to d + 1 of them) and z's derivatives with respect to their x
  // (d x d each) and r (d each).
  std::vector<Eigen::Index> support;
  std::vector<Eigen::MatrixXd> dz_dx;
  std::vector<Eigen::VectorXd> dz_dr;
};

// x: N x d (d = 1 or 2), r: N.
StickCentre stick_centre(const Eigen::MatrixXd& x, const Eigen::VectorXd& r);

}  // namespace hbtrack
