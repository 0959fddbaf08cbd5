#include "case_excitation.hpp"

#include <algorithm>
#include <set>

namespace hbtrack {

void read_forcing_growth(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* growth = in.find(root, "forcing_growth");
  if (!growth) return;
  in.table(*growth, "forcing_growth");
  in.check_keys(*growth, "forcing_growth", {"exponent", "reference_frequency"});
  if (in.find(root, "base_motion"))
    in.fail(growth, "forcing_growth", "cannot be combined with [base_motion] (the kind of base motion sets the growth)");
  if (!in.find(root, "forcing")) in.fail(growth, "forcing_growth", "there is no [[forcing]] for it to scale");
  const toml::value& exponent = in.require(*growth, "exponent", "forcing_growth.exponent");
  const toml::value& reference = in.require(*growth, "reference_frequency", "forcing_growth.reference_frequency");
  ForcingGrowth& g = c.model.forcing_growth;
  g.exponent = in.number(exponent, "forcing_growth.exponent");
  g.reference_frequency = in.number(reference, "forcing_growth.reference_frequency");
  if (g.exponent < 0)
    in.fail(&exponent, "forcing_growth.exponent", "must be >= 0 (the forcing grows as (omega/reference_frequency)^exponent; 0 is fixed)");
  if (g.reference_frequency <= 0)
    in.fail(&reference, "forcing_growth.reference_frequency", "must be > 0 (rad/s: the frequency at which the forcing is as given)");
}

void read_base_motion(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* base = in.find(root, "base_motion");
  if (!base) return;
  in.table(*base, "base_motion");
  in.check_keys(*base, "base_motion", {"kind", "dofs", "harmonic", "cos", "sin"});
  // One excitation: forces and a support motion together would need two growths of the forcing.
  if (in.find(root, "forcing"))
    in.fail(base, "base_motion", "cannot be combined with [[forcing]] (impose the support motion or forces, not both)");
  BaseMotion b;
  in.require(*base, "kind", "base_motion.kind");  // no default: the kind decides the physics
  b.kind = in.choice_or(*base, "kind", BaseMotionKind::displacement);
  const toml::value& dofs = in.require(*base, "dofs", "base_motion.dofs");
  if (!dofs.is_array() || dofs.as_array().empty())
    in.fail(&dofs, "base_motion.dofs", "expected a non-empty array of dof names (the dofs the base carries)");
  std::set<int> seen;
  for (size_t i = 0; i < dofs.as_array().size(); ++i) {
    const std::string field = "base_motion.dofs[" + std::to_string(i) + "]";
    const int d = dof_index(in, c.model, dofs.as_array()[i], field);
    if (!seen.insert(d).second) in.fail(&dofs.as_array()[i], field, "dof listed twice");
    b.dofs.push_back(d);
  }
  b.harmonic = in.integer_or(*base, "harmonic", "base_motion.harmonic", 1);
  if (b.harmonic < 1)
    in.fail(in.find(*base, "harmonic"), "base_motion.harmonic",
            "must be >= 1 (a constant base motion exerts no force on the relative motion)");
  if (!in.find(*base, "cos") && !in.find(*base, "sin")) in.fail(base, "base_motion", "needs cos and/or sin (the motion's amplitudes)");
  b.cos_part = in.number_or(*base, "cos", "base_motion.cos", 0.0);
  b.sin_part = in.number_or(*base, "sin", "base_motion.sin", 0.0);
  try {
    const EquivalentForcing equivalent = base_motion_forcing(c.model, b);
    c.model.forcing.push_back(equivalent.force);
    c.model.forcing_growth = equivalent.growth;
  } catch (const std::invalid_argument& e) {
    in.fail(base, "", e.what());
  }
  c.base_motion = std::move(b);
}

void check_base_motion_within_harmonics(const CaseReader& in, const toml::value& root, const CaseDefinition& c) {
  if (!c.base_motion) return;
  const toml::value* base = in.find(root, "base_motion");
  const toml::value* where = in.find(*base, "harmonic") ? in.find(*base, "harmonic") : base;
  const int order = c.base_motion->harmonic * c.harmonic_balance.subharmonic;
  const std::vector<int> listed = c.harmonic_balance.selected_harmonics();
  if (std::find(listed.begin(), listed.end(), order) == listed.end())
    in.fail(where, "base_motion.harmonic",
            "harmonic " + std::to_string(c.base_motion->harmonic) + " is not among the harmonics balanced (it would be dropped)");
}

}  // namespace hbtrack
