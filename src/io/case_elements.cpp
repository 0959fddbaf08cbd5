#include "case_elements.hpp"

#include <set>

#include "hbtrack/elements/elastic_dry_friction.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/iwan.hpp"
#include "hbtrack/elements/polynomial_elements.hpp"
#include "hbtrack/elements/scalar_elements.hpp"
#include "hbtrack/elements/tip_contact.hpp"

namespace hbtrack {

using Eigen::VectorXd;

namespace {

struct PropertySpec {
  std::string name;
  bool required;
  double fallback;
};

// polynomial_stiffness: `exponents` (one row of nonnegative integers per monomial) now, its
// `coefficients` (same rows, one bindable entry per dof) once the dofs are known.
std::shared_ptr<PolynomialStiffness> read_polynomial_exponents(const CaseReader& in, const toml::value& e, const std::string& field) {
  const toml::value& value = in.require(e, "exponents", field + ".exponents");
  if (!value.is_array() || value.as_array().empty()) in.fail(&value, field + ".exponents", "expected an array of rows, one per monomial");
  const auto& rows = value.as_array();
  Eigen::MatrixXi p;
  for (size_t m = 0; m < rows.size(); ++m) {
    const std::string row_field = field + ".exponents[" + std::to_string(m) + "]";
    if (!rows[m].is_array()) in.fail(&rows[m], row_field, "expected an array of integers, one per dof");
    const auto& row = rows[m].as_array();
    if (m == 0) p.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(row.size()));
    if (static_cast<Eigen::Index>(row.size()) != p.cols()) in.fail(&rows[m], row_field, "every row needs the same length (one exponent per dof)");
    for (size_t j = 0; j < row.size(); ++j) {
      const int exponent = in.integer(row[j], row_field + "[" + std::to_string(j) + "]");
      if (exponent < 0 || exponent > 64) in.fail(&row[j], row_field + "[" + std::to_string(j) + "]", "must be an integer in [0, 64]");
      p(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(j)) = exponent;
    }
  }
  return std::make_shared<PolynomialStiffness>(p);
}

void read_polynomial_coefficients(const CaseReader& in, const toml::value& e, const std::string& field, CaseDefinition& c,
                                  NonlinearElement& element, Eigen::Index monomials) {
  const int k = element.local_dofs();
  const toml::value& value = in.require(e, "coefficients", field + ".coefficients");
  if (!value.is_array() || static_cast<Eigen::Index>(value.as_array().size()) != monomials)
    in.fail(&value, field + ".coefficients", "expected one row per monomial (" + std::to_string(monomials) + ")");
  for (size_t m = 0; m < value.as_array().size(); ++m) {
    const toml::value& row = value.as_array()[m];
    const std::string row_field = field + ".coefficients[" + std::to_string(m) + "]";
    if (!row.is_array() || static_cast<int>(row.as_array().size()) != k)
      in.fail(&row, row_field, "expected one coefficient per dof (" + std::to_string(k) + ")");
    for (size_t i = 0; i < row.as_array().size(); ++i)
      element.properties.push_back(binding(in, c, row.as_array()[i], row_field + "[" + std::to_string(i) + "]"));
  }
}

// The keys that choose an element's variant: `law` (a normal contact law, or penalty / dlft
// for frictional_contact) and tip_contact's `friction`.
struct ElementVariant {
  ContactLawKind law = ContactLawKind::polynomial;
  ContactFormulation formulation = ContactFormulation::penalty;
  TipFriction friction = TipFriction::sliding;
};

template <class Parse>
auto parse_key(const CaseReader& in, const toml::value& v, const std::string& field, Parse parse) {
  try {
    return parse(in.string(v, field));
  } catch (const std::invalid_argument& err) {
    in.fail(&v, field, err.what());
  }
}

ElementVariant read_variant(const CaseReader& in, const toml::value& e, const std::string& type, const std::string& field) {
  ElementVariant v;
  if (const toml::value* l = in.find(e, "law")) {
    if (type == "frictional_contact")
      v.formulation = parse_key(in, *l, field + ".law", parse_contact_formulation);
    else if (type == "regularized_contact" || type == "tip_contact")
      v.law = parse_key(in, *l, field + ".law", parse_contact_law);
  }
  if (const toml::value* f = type == "tip_contact" ? in.find(e, "friction") : nullptr)
    v.friction = parse_key(in, *f, field + ".friction", parse_tip_friction);
  return v;
}

}  // namespace

void read_elements(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* elements = in.find(root, "elements");
  if (!elements) return;
  if (!elements->is_array()) in.fail(elements, "elements", "expected an array of tables ([[elements]])");
  const std::vector<std::string> types{"cubic_spring",         "unilateral_spring", "regularized_contact", "tanh_friction", "tip_contact",
                                       "polynomial_stiffness", "power_damper",      "elastic_dry_friction", "frictional_contact", "iwan"};
  for (size_t i = 0; i < elements->as_array().size(); ++i) {
    const std::string field = "elements[" + std::to_string(i) + "]";
    const toml::value& e = in.table(elements->as_array()[i], field);
    const toml::value& type_value = in.require(e, "type", field + ".type");
    const std::string type = in.string(type_value, field + ".type");
    std::shared_ptr<NonlinearElement> element;
    std::vector<PropertySpec> specs;
    const ElementVariant variant = read_variant(in, e, type, field);
    const ContactLawKind law = variant.law;
    const TipFriction friction = variant.friction;
    if (type == "cubic_spring") {
      element = std::make_shared<CubicSpring>();
      specs = {{"cubic_stiffness", true, 0}};
    } else if (type == "unilateral_spring") {
      element = std::make_shared<GapContact>(ContactLawKind::penalty, type);
      specs = {{"stiffness", true, 0}, {"gap", false, 0.0}, {"width", false, 0.0}};
    } else if (type == "regularized_contact") {
      element = std::make_shared<GapContact>(law, type);
      specs = {{"stiffness", true, 0}, {"gap", false, 0.0}, {"width", true, 0}};
    } else if (type == "tanh_friction") {
      element = std::make_shared<TanhFriction>();
      specs = {{"mu", true, 0}, {"normal_load", true, 0}, {"regularization_velocity", true, 0}};
    } else if (type == "tip_contact") {
      element = std::make_shared<TipContact>(law, friction);
      specs = {{"stiffness", true, 0}, {"clearance", true, 0}, {"width", true, 0}, {"mu", true, 0},
               {"radius", true, 0},    {"engine_order", false, 1.0}, {"rotation_speed", false, 0.0}};
      if (friction == TipFriction::stick_slip) specs.push_back({"tangential_stiffness", true, 0});
    } else if (type == "polynomial_stiffness") {
      element = read_polynomial_exponents(in, e, field);
    } else if (type == "power_damper") {
      element = std::make_shared<PowerDamper>();
      specs = {{"coefficient", true, 0}, {"exponent", false, 2.0}};
    } else if (type == "elastic_dry_friction") {
      element = std::make_shared<ElasticDryFriction>();
      specs = {{"stiffness", true, 0}, {"limit_force", true, 0}};
    } else if (type == "iwan") {
      const toml::value* count = in.find(e, "sliders");
      const int sliders = count ? in.integer(*count, field + ".sliders") : Iwan::kDefaultSliders;
      // Each slider costs a pass over the samples; beyond 1000 the discretisation error (second
      // order in the grid ratio) is far below any identified joint's.
      if (sliders < 2 || sliders > 1000) in.fail(count, field + ".sliders", "must be an integer in [2, 1000]");
      element = std::make_shared<Iwan>(sliders);
      specs = {{"limit_force", true, 0}, {"stiffness", true, 0}, {"chi", true, 0}, {"beta", true, 0}};
    } else if (type == "frictional_contact") {
      element = std::make_shared<FrictionalContact>(variant.formulation);
      if (variant.formulation == ContactFormulation::penalty)
        specs = {{"normal_stiffness", true, 0}, {"tangential_stiffness", true, 0}, {"mu", true, 0}, {"normal_preload", false, 0.0}};
      else
        specs = {{"mu", true, 0}, {"epsilon", true, 0}, {"gap", false, 0.0}};
    } else {
      const std::string guess = nearest(type, types);
      in.fail(&type_value, field + ".type", "unknown element type '" + type + "'" +
                                                 (guess.empty() ? " (expected one of: " + join(types) + ")" : " (did you mean '" + guess + "'?)"));
    }
    // Templates are expanded before the overrides: only `--set elements[i].nodes=...` gets here.
    if (const toml::value* nodes = in.find(e, "nodes"))
      in.fail(nodes, field + ".nodes", "templates are expanded before --set: set the expanded elements' keys instead");
    std::vector<std::string> allowed{"type", "dofs", "lanczos"};
    if (type == "regularized_contact" || type == "tip_contact" || type == "frictional_contact") allowed.push_back("law");
    if (type == "tip_contact") allowed.push_back("friction");
    const bool polynomial = type == "polynomial_stiffness";
    const bool scalar = type != "tip_contact" && type != "frictional_contact" && !polynomial;
    if (scalar) allowed.push_back("weights");
    if (polynomial) allowed.insert(allowed.end(), {"exponents", "coefficients"});
    if (type == "iwan") allowed.push_back("sliders");
    for (const auto& s : specs) allowed.push_back(s.name);
    in.check_keys(e, field, allowed);

    const toml::value& dofs_value = in.require(e, "dofs", field + ".dofs");
    if (!dofs_value.is_array() && !dofs_value.is_string()) in.fail(&dofs_value, field + ".dofs", "expected an array of dof names");
    std::vector<toml::value> dof_values = dofs_value.is_array() ? dofs_value.as_array() : std::vector<toml::value>{dofs_value};
    for (size_t d = 0; d < dof_values.size(); ++d)
      element->dofs.push_back(dof_index(in, c.model, dof_values[d], field + ".dofs[" + std::to_string(d) + "]"));
    const int k = element->local_dofs();
    if (type == "tip_contact" && k != 3)
      in.fail(&dofs_value, field + ".dofs", "expected 3 dofs [radial, circumferential, axial], got " + std::to_string(k));
    if (type == "frictional_contact" && k != 2) in.fail(&dofs_value, field + ".dofs", "expected 2 dofs [normal, tangential], got " + std::to_string(k));
    if (scalar && (k < 1)) in.fail(&dofs_value, field + ".dofs", "expected at least one dof");
    if (std::set<int>(element->dofs.begin(), element->dofs.end()).size() != element->dofs.size())
      in.fail(&dofs_value, field + ".dofs", "a dof appears twice");
    if (scalar) {
      auto* s = static_cast<ScalarElement*>(element.get());
      if (const toml::value* w = in.find(e, "weights")) {
        s->weights = in.vector(*w, field + ".weights");
        if (s->weights.size() != k) in.fail(w, field + ".weights", "expected one weight per dof (" + std::to_string(k) + ")");
        if (s->weights.isZero(0.0)) in.fail(w, field + ".weights", "must not all be zero (the element would act on nothing)");
      } else if (k == 1) {
        s->weights = VectorXd::Ones(1);
      } else if (k == 2) {
        s->weights = (VectorXd(2) << 1.0, -1.0).finished();  // relative displacement x_a - x_b
      } else {
        in.fail(&e, field + ".weights", "required for more than two dofs");
      }
    }
    if (polynomial) {
      const auto& exponents = static_cast<PolynomialStiffness*>(element.get())->exponents();
      if (exponents.cols() != k) in.fail(&e.at("exponents"), field + ".exponents", "expected one exponent per dof (" + std::to_string(k) + ") in each row");
      read_polynomial_coefficients(in, e, field, c, *element, exponents.rows());
    }
    for (const auto& spec : specs) {
      const toml::value* v = in.find(e, spec.name);
      if (!v && spec.required) in.fail(&e, field + "." + spec.name, "missing (required for " + type + ")");
      element->properties.push_back(v ? binding(in, c, *v, field + "." + spec.name) : ParameterBinding::constant(spec.fallback));
    }
    // Physical ranges at the nominal parameter values.
    const std::vector<double> values = element->property_values(c.parameters);
    for (size_t p = 0; p < specs.size(); ++p) {
      const std::string& name = specs[p].name;
      const bool must_be_positive = name == "stiffness" || name == "normal_stiffness" || name == "tangential_stiffness" || name == "regularization_velocity" || name == "epsilon" ||
                                    (name == "width" && type != "unilateral_spring") || name == "radius" ||
                                    (name == "limit_force" && type == "iwan");
      // The sign of engine_order is the sense of rotation (rotor 67 and the parametric blade
      // turn towards -theta of their tip frames); 0 would stop the rotor, and leave permanent
      // sliding without a direction (stick-slip friction does without).
      const bool must_be_nonzero = name == "engine_order" && friction == TipFriction::sliding;
      const bool must_be_nonnegative = name == "mu" || name == "normal_load" || name == "clearance" || name == "limit_force" || name == "beta";
      const toml::value* v = in.find(e, name);
      if (must_be_positive && !(values[p] > 0)) in.fail(v ? v : &e, field + "." + name, "must be > 0");
      if (must_be_nonzero && !(values[p] != 0)) in.fail(v ? v : &e, field + "." + name, "must be nonzero (its sign is the sense of rotation)");
      if (must_be_nonnegative && values[p] < 0) in.fail(v ? v : &e, field + "." + name, "must be >= 0");
      if (name == "chi" && !(values[p] > -1)) in.fail(v ? v : &e, field + "." + name, "must be > -1 (the slider density phi^chi is not integrable at 0 otherwise)");
      if (name == "exponent" && !(values[p] >= 1)) in.fail(v ? v : &e, field + "." + name, "must be >= 1 (the force derivative is unbounded at zero velocity below 1)");
    }
    element->lanczos_exponent = in.number_or(e, "lanczos", field + ".lanczos", 0.0);
    if (element->lanczos_exponent < 0) in.fail(&e.at("lanczos"), field + ".lanczos", "must be >= 0 (0 disables the filter)");
    // sinc(j/(H+1))^p: beyond p = 10 the higher harmonics of the force vanish (1e9 removed them all).
    if (element->lanczos_exponent > 10) in.fail(&e.at("lanczos"), field + ".lanczos", "must be <= 10");
    c.elements.push_back(std::move(element));
  }
}

}  // namespace hbtrack
