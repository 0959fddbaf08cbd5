// The harmonic balance system's construction (retained dofs, condensation, the elements' static
// data) and its options; the evaluations are in harmonic_balance.cpp.
#include "hbtrack/hbm/harmonic_balance_system.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "hbtrack/elements/lanczos.hpp"

namespace hbtrack {

namespace {
std::string list_text(const std::vector<int>& list) {
  std::string text = "[";
  for (size_t i = 0; i < list.size(); ++i) text += (i ? ", " : "") + std::to_string(list[i]);
  return text + "]";
}
}  // namespace

std::vector<int> HarmonicBalanceOptions::selected_harmonics() const {
  if (!harmonic_list.empty()) return harmonic_list;
  std::vector<int> all;
  for (int k = 0; k <= harmonics; ++k) all.push_back(k);
  return all;
}

void HarmonicBalanceOptions::select(const std::vector<int>& list) {
  bool full = !list.empty() && list.front() == 0;
  for (size_t i = 0; full && i < list.size(); ++i) full = list[i] == static_cast<int>(i);
  harmonic_list = full ? std::vector<int>{} : list;
  if (!list.empty()) harmonics = list.back();
}

std::string harmonic_label(int k, int subharmonic) {
  if (subharmonic <= 1 || k % subharmonic == 0) return std::to_string(subharmonic <= 1 ? k : k / subharmonic);
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", static_cast<double>(k) / subharmonic);
  return text;
}

void HarmonicBalanceOptions::validate() const {
  if (!harmonic_list.empty()) {
    const std::string got = ", got " + list_text(harmonic_list);
    for (size_t i = 0; i < harmonic_list.size(); ++i) {
      if (harmonic_list[i] < 0)
        throw std::invalid_argument("harmonic_balance.harmonics: a list of harmonics must hold integers >= 0" + got);
      if (i > 0 && harmonic_list[i] <= harmonic_list[i - 1])
        throw std::invalid_argument("harmonic_balance.harmonics: a list of harmonics must be sorted and unique (increasing)" + got);
    }
    if (harmonic_list.back() < 1) throw std::invalid_argument("harmonic_balance.harmonics: a list of harmonics needs one >= 1" + got);
    if (harmonics != harmonic_list.back())
      throw std::invalid_argument("harmonic_balance.harmonics: H = " + std::to_string(harmonics) + " is not the list's largest" + got);
  }
  if (subharmonic < 1 || subharmonic > 16)
    throw std::invalid_argument("harmonic_balance.subharmonic: must be in [1, 16], got " + std::to_string(subharmonic));
  if (harmonics < 1) throw std::invalid_argument("harmonic_balance.harmonics: must be >= 1, got " + std::to_string(harmonics));
  if (harmonics > 500) throw std::invalid_argument("harmonic_balance.harmonics: must be <= 500, got " + std::to_string(harmonics));
  if (samples != 0 && samples < 2 * harmonics + 1)
    throw std::invalid_argument("harmonic_balance.samples: must be >= 2*harmonics+1 = " + std::to_string(2 * harmonics + 1) + ", got " +
                                std::to_string(samples));
  if (samples > (1 << 20)) throw std::invalid_argument("harmonic_balance.samples: must be <= 1048576");
  if (!adaptive.enabled()) return;
  adaptive.validate();
  // It adds and drops the top harmonic of 0..H, of omega itself.
  if (!harmonic_list.empty()) throw std::invalid_argument("harmonic_balance.adaptive: not with a list of harmonics (it changes H of 0..H)");
  if (subharmonic != 1)
    throw std::invalid_argument("harmonic_balance.adaptive: not with subharmonic = " + std::to_string(subharmonic) +
                                " (harmonics of omega only)");
  if (harmonics < adaptive.min || harmonics > adaptive.max)
    throw std::invalid_argument(
        "harmonic_balance.harmonics: the H an adaptive run starts from must lie in [adaptive.min, adaptive.max] = [" +
        std::to_string(adaptive.min) + ", " + std::to_string(adaptive.max) + "], got " + std::to_string(harmonics));
  if (samples != 0 && samples < 2 * adaptive.max + 1)
    throw std::invalid_argument("harmonic_balance.samples: must be >= 2*adaptive.max+1 = " + std::to_string(2 * adaptive.max + 1) +
                                ", got " + std::to_string(samples));
}

int HarmonicBalanceOptions::effective_samples() const {
  if (samples > 0) return samples;
  int n = 16;
  while (n < 8 * (harmonics + 1)) n *= 2;
  return n;
}

HarmonicBalanceSystem::HarmonicBalanceSystem(StructuralModel model, ElementList elements, ParameterSet parameters,
                                             HarmonicBalanceOptions options)
    : model_(std::move(model)),
      elements_(std::move(elements)),
      parameters_(std::move(parameters)),
      options_(std::move(options)),
      basis_((options_.validate(), options_.selected_harmonics()), options_.effective_samples()) {
  model_.validate();
  const std::vector<int>& listed = basis_.harmonic_numbers();
  for (const HarmonicForce& h : model_.forcing)
    if (std::find(listed.begin(), listed.end(), h.order * options_.subharmonic) == listed.end())
      throw std::invalid_argument("forcing harmonic " + std::to_string(h.order) + " is not among the harmonics balanced, " +
                                  list_text(listed) + (options_.subharmonic > 1 ? " x omega/" + std::to_string(options_.subharmonic) : "") +
                                  " (it would be dropped)");
  for (int c = 0; c < basis_.coefficients(); ++c)
    if (c == 0 || basis_.harmonic_of(c) != basis_.harmonic_of(c - 1)) slot_offset_.push_back(c);
  // The condensers' harmonic j is at j * fundamental: the forcing's order h is harmonic h nu.
  StructuralModel linear_model = model_;
  for (HarmonicForce& h : linear_model.forcing) h.order *= options_.subharmonic;
  amplitude_index_ = parameters_.find("amplitude");
  if (amplitude_index_ < 0) amplitude_index_ = parameters_.set("amplitude", 1.0);

  std::set<int> nonlinear;
  for (const auto& e : elements_) {
    if (static_cast<int>(e->properties.size()) != static_cast<int>(e->property_names().size()))
      throw std::invalid_argument("element " + e->type() + ": property count does not match");
    for (int d : e->dofs) {
      if (d < 0 || d >= model_.dofs()) throw std::invalid_argument("element " + e->type() + ": dof index out of range");
      nonlinear.insert(d);
    }
  }
  Condensation method = options_.condensation;
  if (nonlinear.empty()) method = Condensation::none;  // a linear model: keep every dof as unknown
  if (method == Condensation::none) {
    for (int i = 0; i < model_.dofs(); ++i) retained_.push_back(i);
  } else {
    retained_.assign(nonlinear.begin(), nonlinear.end());
  }
  // Modal condensation inverts the retained dofs' receptance, a sum over every mode: with many
  // retained dofs (the blade's 27 tip dofs of 39) it is ill-conditioned (1e7 near a resonance)
  // and Newton stalls, while the Schur complement of a small linear block is cheap anyway. So
  // `auto` takes modal only when the retained dofs are a small part of the model.
  if (method == Condensation::automatic) {
    const bool few_retained = 4 * retained_.size() <= static_cast<size_t>(model_.dofs());
    method = few_retained && modes_diagonalise_damping(model_) ? Condensation::modal : Condensation::schur;
  }
  if (method == Condensation::modal) {
    if (!modes_diagonalise_damping(model_))
      throw std::invalid_argument(
          "harmonic_balance.condensation: 'modal' needs damping diagonalised by the normal modes and K > 0; use 'schur'");
    condenser_ = make_modal_condenser(linear_model, retained_, options_.harmonics);
  } else {
    condenser_ = make_schur_condenser(linear_model, retained_, options_.harmonics);
  }

  // An element that reads the linear residual at its dofs (DLFT) must be alone on them: another
  // element's force there would be part of what the contact balances.
  for (size_t e = 0; e < elements_.size(); ++e) {
    if (!elements_[e]->uses_linear_residual()) continue;
    residual_elements_ = true;
    if (elements_[e]->lanczos_exponent != 0.0)
      throw std::invalid_argument("element " + elements_[e]->type() + " reads the linear residual (DLFT): no Lanczos filter on it");
    for (size_t o = 0; o < elements_.size(); ++o)
      for (int d : elements_[o]->dofs)
        if (o != e && std::find(elements_[e]->dofs.begin(), elements_[e]->dofs.end(), d) != elements_[e]->dofs.end())
          throw std::invalid_argument("element " + elements_[e]->type() + " reads the linear residual (DLFT) at dof " +
                                      model_.dof_names[static_cast<size_t>(d)] + ", which another element (" + elements_[o]->type() +
                                      ") also acts on");
  }
  slots_.resize(elements_.size());
  for (size_t e = 0; e < elements_.size(); ++e) {
    ElementSlot& s = slots_[e];
    for (int d : elements_[e]->dofs)
      s.columns.push_back(static_cast<int>(std::lower_bound(retained_.begin(), retained_.end(), d) - retained_.begin()));
    const Eigen::VectorXd dense_sigma = lanczos_factors(options_.harmonics, elements_[e]->lanczos_exponent);
    s.sigma.resize(basis_.coefficients());
    for (int c = 0; c < basis_.coefficients(); ++c) s.sigma(c) = dense_sigma(basis_.dense_index(c));
  }
}

HarmonicBalanceWorkspace::HarmonicBalanceWorkspace(const HarmonicBalanceSystem& system)
    : system_(&system), elements_(system.elements().size()) {
  const int n_samples = system.basis().samples();
  for (size_t e = 0; e < elements_.size(); ++e) {
    elements_[e].x.resize(n_samples, system.elements()[e]->local_dofs());
    elements_[e].v.resize(n_samples, system.elements()[e]->local_dofs());
  }
}

void HarmonicBalanceSystem::check(const ParameterValues& p, const HarmonicBalanceWorkspace& ws) const {
  if (ws.system_ != this) throw std::logic_error("HarmonicBalanceSystem: a workspace made for another system");
  if (static_cast<int>(p.size()) != parameters_.size())
    throw std::logic_error("HarmonicBalanceSystem: " + std::to_string(p.size()) + " parameter values for " +
                           std::to_string(parameters_.size()) + " parameters");
}

}  // namespace hbtrack
