#pragma once
// The Craig-Bampton boundary of a generated blade (parametric or from sections): its tip nodes'
// three dofs in each node's cylindrical frame, as `hbtrack reduce` keeps them.
#include <vector>

#include "hbtrack/model/craig_bampton.hpp"

namespace hbtrack::test {

template <class Blade>
std::vector<CraigBamptonBoundaryNode> tip_boundary(const Blade& blade) {
  std::vector<CraigBamptonBoundaryNode> boundary;
  for (size_t j = 0; j < blade.tip_nodes.size(); ++j) {
    CraigBamptonBoundaryNode b;
    for (int d = 0; d < 3; ++d) b.dofs[static_cast<size_t>(d)] = blade.dofs.dof(blade.tip_nodes[j], d);
    b.frame = blade.tip_frames[j].directions;
    boundary.push_back(b);
  }
  return boundary;
}

}  // namespace hbtrack::test
