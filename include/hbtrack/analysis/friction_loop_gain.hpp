#pragma once
// Whether dry friction at a contact feeds its own normal load: the static loop gain of each
// frictional contact element (NonlinearElement::friction_coupling), from the structure's static
// flexibility G = K^-1 at the element's normal (n) and tangential (t) dofs.
// A contact force f_N pushes the structure off the contact (-n) and friction drags it along
// `sense` t, so the normal displacement towards the contact is
//   x_n = -f_N G_nn (1 - ratio),  ratio = mu G_nt / G_nn,
// G_nt the normal displacement per unit force along `sense` t. With f_N = k x_n in contact the
// loop x_n -> f_N -> x_n has the gain k G_nn (ratio - 1). Above 1 the contact's static tangent
// is negative: friction pushes the node into the contact more than the contact pushes it out,
// and a rigid contact (k -> infinity) has no well-posed answer wherever ratio > 1 (a
// Painleve-type paradox): the penalty stiffness sets the result.
#include <optional>
#include <string>
#include <vector>

#include "hbtrack/elements/nonlinear_element.hpp"
#include "hbtrack/model/parameters.hpp"
#include "hbtrack/model/structural_model.hpp"

namespace hbtrack {

struct FrictionLoopGain {
  int element = 0;  // index in the element list
  std::string type;
  std::string normal_dof, tangential_dof;  // the model's dof names
  // The sense along the tangential dof in which friction pushes the structure: the law's (a
  // turning casing), or, where the motion sets it (sense_from_law false), the worse of the two.
  int sense = 1;
  bool sense_from_law = true;
  double mu = 0;
  double stiffness = 0;          // k_n; 0 for a rigid contact
  double flexibility_nn = 0;     // G_nn = (K^-1)_nn
  double flexibility_nt = 0;     // sense (K^-1)_nt
  double ratio = 0;              // mu G_nt / G_nn
  std::optional<double> gain;    // k G_nn (ratio - 1); none for a rigid contact (infinite when ratio > 1)
  bool self_energising = false;  // gain > 1 (a rigid contact: ratio > 1)
  // With ratio > 1: the stiffness k above which the gain exceeds 1, 1 / (G_nn (ratio - 1)).
  std::optional<double> critical_stiffness;
  // Why no gain could be computed ("" when it was): K singular or not positive at the dof.
  std::string note;
};

// Every element with a friction coupling, in list order; `values` the parameter values. The
// sliding sense of a law that turns with omega is read at both ends of [omega_a, omega_b]: when
// they differ (or the law has none) the worse sense is taken. Nothing is factorised when no
// element has friction.
std::vector<FrictionLoopGain> friction_loop_gains(const StructuralModel& model, const ElementList& elements, const ParameterValues& values,
                                                  double omega_a, double omega_b);

}  // namespace hbtrack
