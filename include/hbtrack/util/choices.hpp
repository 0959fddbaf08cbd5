#pragma once
// Every named choice of the settings as an enum, with its names in one table each. The names are
// the case file's values, and summary.json's and Python's: renaming one changes those formats.
// parse_X reads a name and throws std::invalid_argument "<field>: must be a, b or c, got 'x'"
// (`field` defaults to the case file's key); to_string gives the name back.
// To add a choice: its enum, a ChoiceTable specialisation (field and names), a parse_X.
#include <span>
#include <string>
#include <string_view>

namespace hbtrack {

enum class Predictor { tangent, secant };                   // paper eq 12
enum class Corrector { pseudo_arclength, hypersphere };     // paper eq 14
enum class Condensation { automatic, schur, modal, none };  // none: solve the full system
// Floquet exponents by Hill's method, the monodromy matrix, or shooting (a monodromy matrix on
// the converged periodic orbit); none: no stability analysis.
enum class StabilityMethod { hill, monodromy, shooting, none };
enum class HillSolver { automatic, dense, arnoldi };                 // see stability/hill.hpp
enum class CrossCheck { automatic, off };                            // see StabilityOptions::cross_check
enum class TrackingMethod { bordered, extended };                    // minimally augmented | the paper's system
enum class IntegrationMethod { newmark, dopri5 };                    // simulate: HHT-alpha | Dormand-Prince
enum class BaseMotionKind { displacement, velocity, acceleration };  // what [base_motion] imposes

template <class Choice>
struct ChoiceName {
  Choice value;
  std::string_view name;
};

// Per choice: `field`, the case-file key its errors name, and `names`, every value once.
template <class Choice>
struct ChoiceTable;

template <>
struct ChoiceTable<Predictor> {
  static constexpr std::string_view field = "continuation.predictor";
  static constexpr ChoiceName<Predictor> names[] = {{Predictor::tangent, "tangent"}, {Predictor::secant, "secant"}};
};
template <>
struct ChoiceTable<Corrector> {
  static constexpr std::string_view field = "continuation.corrector";
  static constexpr ChoiceName<Corrector> names[] = {{Corrector::pseudo_arclength, "pseudo_arclength"},
                                                    {Corrector::hypersphere, "hypersphere"}};
};
template <>
struct ChoiceTable<Condensation> {
  static constexpr std::string_view field = "harmonic_balance.condensation";
  static constexpr ChoiceName<Condensation> names[] = {
      {Condensation::automatic, "auto"}, {Condensation::schur, "schur"}, {Condensation::modal, "modal"}, {Condensation::none, "none"}};
};
template <>
struct ChoiceTable<StabilityMethod> {
  static constexpr std::string_view field = "stability.method";
  static constexpr ChoiceName<StabilityMethod> names[] = {{StabilityMethod::hill, "hill"},
                                                          {StabilityMethod::monodromy, "monodromy"},
                                                          {StabilityMethod::shooting, "shooting"},
                                                          {StabilityMethod::none, "none"}};
};
template <>
struct ChoiceTable<HillSolver> {
  static constexpr std::string_view field = "stability.hill_solver";
  static constexpr ChoiceName<HillSolver> names[] = {
      {HillSolver::automatic, "auto"}, {HillSolver::dense, "dense"}, {HillSolver::arnoldi, "arnoldi"}};
};
template <>
struct ChoiceTable<CrossCheck> {
  static constexpr std::string_view field = "stability.cross_check";
  static constexpr ChoiceName<CrossCheck> names[] = {{CrossCheck::automatic, "auto"}, {CrossCheck::off, "off"}};
};
template <>
struct ChoiceTable<TrackingMethod> {
  static constexpr std::string_view field = "tracking method";
  static constexpr ChoiceName<TrackingMethod> names[] = {{TrackingMethod::bordered, "bordered"}, {TrackingMethod::extended, "extended"}};
};

template <>
struct ChoiceTable<IntegrationMethod> {
  static constexpr std::string_view field = "method";  // not in the case file: the argument's name
  static constexpr ChoiceName<IntegrationMethod> names[] = {{IntegrationMethod::newmark, "newmark"}, {IntegrationMethod::dopri5, "dopri5"}};
};

template <>
struct ChoiceTable<BaseMotionKind> {
  static constexpr std::string_view field = "base_motion.kind";
  static constexpr ChoiceName<BaseMotionKind> names[] = {{BaseMotionKind::displacement, "displacement"},
                                                         {BaseMotionKind::velocity, "velocity"},
                                                         {BaseMotionKind::acceleration, "acceleration"}};
};

template <class Choice>
concept NamedChoice = requires {
  ChoiceTable<Choice>::names;
};

// "<field>: must be a, b or c, got 'name'", the names in their table's order.
[[noreturn]] void throw_unknown_choice(std::string_view field, std::span<const std::string_view> names, const std::string& name);

template <NamedChoice Choice>
Choice parse_choice(const std::string& name, std::string_view field = ChoiceTable<Choice>::field) {
  constexpr auto& table = ChoiceTable<Choice>::names;
  for (const ChoiceName<Choice>& entry : table)
    if (entry.name == name) return entry.value;
  std::string_view names[std::size(table)];
  for (std::size_t i = 0; i < std::size(table); ++i) names[i] = table[i].name;
  throw_unknown_choice(field, names, name);
}

template <NamedChoice Choice>
std::string to_string(Choice value) {
  for (const ChoiceName<Choice>& entry : ChoiceTable<Choice>::names)
    if (entry.value == value) return std::string(entry.name);
  return "?";  // only a value cast from an integer outside the enum
}

inline Predictor parse_predictor(const std::string& name) { return parse_choice<Predictor>(name); }
inline Corrector parse_corrector(const std::string& name) { return parse_choice<Corrector>(name); }
inline Condensation parse_condensation(const std::string& name) { return parse_choice<Condensation>(name); }
inline StabilityMethod parse_stability_method(const std::string& name) { return parse_choice<StabilityMethod>(name); }
inline HillSolver parse_hill_solver(const std::string& name) { return parse_choice<HillSolver>(name); }
inline CrossCheck parse_cross_check(const std::string& name) { return parse_choice<CrossCheck>(name); }
inline TrackingMethod parse_tracking_method(const std::string& name) { return parse_choice<TrackingMethod>(name); }
inline IntegrationMethod parse_integration_method(const std::string& name) { return parse_choice<IntegrationMethod>(name); }
inline BaseMotionKind parse_base_motion_kind(const std::string& name) { return parse_choice<BaseMotionKind>(name); }

}  // namespace hbtrack
