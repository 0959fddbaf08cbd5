#include "hbtrack/analysis/friction_loop_gain.hpp"

#include <cmath>
#include <limits>

namespace hbtrack {

namespace {

struct Coupled {
  int element;
  FrictionCoupling coupling;
  bool sense_from_law;
};

// The sense of a law that fixes it over the whole range, else 0 (the motion decides).
int sense_over_range(const NonlinearElement& e, const std::vector<double>& p, double omega_a, double omega_b) {
  const auto a = e.friction_coupling(p, omega_a), b = e.friction_coupling(p, omega_b);
  return a->sense == b->sense ? a->sense : 0;
}

}  // namespace

std::vector<FrictionLoopGain> friction_loop_gains(const StructuralModel& model, const ElementList& elements, const ParameterValues& values,
                                                  double omega_a, double omega_b) {
  std::vector<Coupled> coupled;
  for (size_t i = 0; i < elements.size(); ++i) {
    const NonlinearElement& e = *elements[i];
    const std::vector<double> p = e.property_values(values);
    std::optional<FrictionCoupling> c = e.friction_coupling(p, omega_a);
    if (!c) continue;
    c->sense = sense_over_range(e, p, omega_a, omega_b);
    coupled.push_back({static_cast<int>(i), *c, c->sense != 0});
  }
  if (coupled.empty()) return {};

  // One factorisation, two columns of K^-1 per element: its normal and tangential dofs.
  const Eigen::Index n = model.stiffness.rows();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(model.stiffness);
  // A rigid-body mode leaves K singular: its pivots fall to round-off.
  const bool singular = !(lu.rcond() > static_cast<double>(n) * std::numeric_limits<double>::epsilon());
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, 2 * static_cast<Eigen::Index>(coupled.size()));
  for (size_t k = 0; k < coupled.size(); ++k) {
    const NonlinearElement& e = *elements[static_cast<size_t>(coupled[k].element)];
    unit(e.dofs[static_cast<size_t>(coupled[k].coupling.normal)], 2 * static_cast<Eigen::Index>(k)) = 1.0;
    unit(e.dofs[static_cast<size_t>(coupled[k].coupling.tangential)], 2 * static_cast<Eigen::Index>(k) + 1) = 1.0;
  }
  const Eigen::MatrixXd columns = singular ? Eigen::MatrixXd() : Eigen::MatrixXd(lu.solve(unit));

  std::vector<FrictionLoopGain> gains;
  for (size_t k = 0; k < coupled.size(); ++k) {
    const Coupled& c = coupled[k];
    const NonlinearElement& e = *elements[static_cast<size_t>(c.element)];
    const int dof_n = e.dofs[static_cast<size_t>(c.coupling.normal)];
    const int dof_t = e.dofs[static_cast<size_t>(c.coupling.tangential)];
    FrictionLoopGain g;
    g.element = c.element;
    g.type = e.type();
    g.normal_dof = model.dof_names[static_cast<size_t>(dof_n)];
    g.tangential_dof = model.dof_names[static_cast<size_t>(dof_t)];
    g.sense_from_law = c.sense_from_law;
    g.mu = c.coupling.mu;
    g.stiffness = c.coupling.stiffness;
    if (singular) {
      g.note = "the stiffness matrix is singular (a rigid-body motion): no static flexibility";
      gains.push_back(g);
      continue;
    }
    const Eigen::Index col = 2 * static_cast<Eigen::Index>(k);
    const double g_nn = columns(dof_n, col);      // normal displacement per unit normal force
    const double g_nt = columns(dof_n, col + 1);  // normal displacement per unit force along +t
    if (!(g_nn > 0)) {
      g.note = "K^-1 is not positive at " + g.normal_dof + ": the structure is not statically stable there";
      gains.push_back(g);
      continue;
    }
    // Free to choose, friction acts in the sense that pushes the node into the contact.
    g.sense = c.sense_from_law ? c.coupling.sense : (g_nt < 0 ? -1 : 1);
    g.flexibility_nn = g_nn;
    g.flexibility_nt = g.sense * g_nt;
    g.ratio = g.mu * g.flexibility_nt / g_nn;
    if (g.stiffness > 0) {
      g.gain = g.stiffness * g_nn * (g.ratio - 1.0);
      g.self_energising = *g.gain > 1.0;
    } else {
      g.self_energising = g.ratio > 1.0;
    }
    if (g.ratio > 1.0) g.critical_stiffness = 1.0 / (g_nn * (g.ratio - 1.0));
    gains.push_back(g);
  }
  return gains;
}

}  // namespace hbtrack
