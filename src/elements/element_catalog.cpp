#include "hbtrack/elements/element_catalog.hpp"

#include "hbtrack/elements/elastic_dry_friction.hpp"
#include "hbtrack/elements/elastic_dry_friction_2d.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/iwan.hpp"
#include "hbtrack/elements/polynomial_elements.hpp"
#include "hbtrack/elements/scalar_elements.hpp"
#include "hbtrack/elements/tip_contact.hpp"

namespace hbtrack {

std::string to_string(PropertyRange range) {
  switch (range) {
    case PropertyRange::any:
      return "";
    case PropertyRange::positive:
      return "> 0";
    case PropertyRange::nonnegative:
      return ">= 0";
    case PropertyRange::nonzero:
      return "!= 0";
    case PropertyRange::above_minus_one:
      return "> -1";
    case PropertyRange::at_least_one:
      return ">= 1";
  }
  return "";
}

bool admits(PropertyRange range, double value) {
  switch (range) {
    case PropertyRange::any:
      return true;
    case PropertyRange::positive:
      return value > 0;
    case PropertyRange::nonnegative:
      return value >= 0;
    case PropertyRange::nonzero:
      return value != 0;
    case PropertyRange::above_minus_one:
      return value > -1;
    case PropertyRange::at_least_one:
      return value >= 1;
  }
  return false;
}

namespace {

using Range = PropertyRange;

// The choice `key` of a setup through the element's own parser, whose message names the values.
template <class Parse>
auto choice(const ElementSetup& setup, const std::string& key, Parse parse) {
  try {
    return parse(setup.choices.at(key));
  } catch (const std::invalid_argument& e) {
    throw ElementKeyError(key, e.what());
  }
}

const ElementKey kContactLaw{"law",
                             ElementKey::Kind::choice,
                             {"polynomial", "penalty", "sqrt"},
                             "polynomial",
                             0,
                             0,
                             "",
                             "",
                             "the normal contact law: penalty (C0), polynomial (C1 blend over width), sqrt (smooth)"};

PropertySpec stiffness(const std::string& name = "stiffness", const std::string& doc = "contact stiffness k") {
  return {name, "F/L", Range::positive, {}, doc};
}
PropertySpec mu() { return {"mu", "1", Range::nonnegative, {}, "friction coefficient"}; }
PropertySpec gap() { return {"gap", "L", Range::any, 0.0, "the force acts once d exceeds the gap"}; }

// The sign of engine_order is the sense of rotation (rotor 67 and the parametric blade turn
// towards -theta of their tip frames); 0 would stop the rotor, and leave permanent sliding
// without a direction (stick-slip friction does without).
ElementBuild tip_contact(const ElementSetup& s) {
  const TipFriction friction = choice(s, "friction", parse_tip_friction);
  const bool sliding = friction == TipFriction::sliding;
  ElementBuild b{std::make_shared<TipContact>(choice(s, "law", parse_contact_law), friction),
                 {stiffness("stiffness", "radial contact stiffness of the casing"),
                  {"clearance", "L", Range::nonnegative, {}, "radial gap between tip and casing"},
                  {"width", "F", Range::positive, {}, "regularisation half-width of the contact law"},
                  mu(),
                  {"radius", "L", Range::positive, {}, "radius of the tip node (casing speed = W radius)"},
                  {"engine_order", "1", sliding ? Range::nonzero : Range::any, 1.0,
                   "rotation speed W = engine_order omega + rotation_speed", sliding ? "its sign is the sense of rotation" : ""},
                  {"rotation_speed", "rad/s", Range::any, 0.0, "the rotation speed that does not follow omega"}}};
  if (!sliding) b.properties.push_back(stiffness("tangential_stiffness", "stiffness of the stick-slip slider"));
  return b;
}

ElementBuild frictional_contact(const ElementSetup& s) {
  const ContactFormulation law = choice(s, "law", parse_contact_formulation);
  if (law == ContactFormulation::penalty)
    return ElementBuild{std::make_shared<FrictionalContact>(law),
                        {stiffness("normal_stiffness", "normal penalty stiffness k_n"),
                         stiffness("tangential_stiffness", "stiffness k_t of the Jenkins slider"),
                         mu(),
                         {"normal_preload", "F", Range::any, 0.0, "normal force at x_n = 0: N = max(0, preload + k_n x_n)"}}};
  return ElementBuild{
      std::make_shared<FrictionalContact>(law),
      {mu(), {"epsilon", "F/L", Range::positive, {}, "penalty factor of the augmented Lagrangian (a convergence factor)"}, gap()}};
}

std::vector<ElementType> make_catalog() {
  return {
      {"cubic_spring",
       "f = cubic_stiffness d^3",
       true,
       {},
       {},
       [](const ElementSetup&) {
         return ElementBuild{std::make_shared<CubicSpring>(), {{"cubic_stiffness", "F/L^3", Range::any, {}, "k3 of f = k3 d^3"}}};
       }},
      {"unilateral_spring",
       "f = stiffness max(0, d - gap) (penalty contact, C0)",
       true,
       {},
       {},
       [](const ElementSetup&) {
         // width: the regularisation of the other contact laws, which the penalty law ignores.
         return ElementBuild{std::make_shared<GapContact>(ContactLawKind::penalty, "unilateral_spring"),
                             {stiffness(), gap(), {"width", "F", Range::any, 0.0, "ignored (the penalty law is not regularised)"}}};
       }},
      {"regularized_contact",
       "f = stiffness max(0, d - gap), regularised over width by `law`",
       true,
       {},
       {kContactLaw},
       [](const ElementSetup& s) {
         return ElementBuild{std::make_shared<GapContact>(choice(s, "law", parse_contact_law), "regularized_contact"),
                             {stiffness(), gap(), {"width", "F", Range::positive, {}, "regularisation half-width of the contact law"}}};
       }},
      {"tanh_friction",
       "f = mu normal_load tanh(d' / regularization_velocity)",
       true,
       {},
       {},
       [](const ElementSetup&) {
         return ElementBuild{std::make_shared<TanhFriction>(),
                             {mu(),
                              {"normal_load", "F", Range::nonnegative, {}, "constant normal load N"},
                              {"regularization_velocity", "L/s", Range::positive, {}, "velocity over which the force saturates"}}};
       }},
      {"polynomial_stiffness",
       "f_i = sum_m coefficients[m][i] prod_j x_j^exponents[m][j]",
       false,
       {},
       {{"exponents", ElementKey::Kind::integer_rows, {}, "", 0, 64, "monomial", "exponent", "one row of exponents per monomial"},
        {"coefficients",
         ElementKey::Kind::property_rows,
         {},
         "",
         0,
         0,
         "monomial",
         "coefficient",
         "one row per monomial, one bindable coefficient per dof"}},
       [](const ElementSetup& s) {
         // The properties coefficients[m][i] come as the rows of `coefficients`.
         return ElementBuild{std::make_shared<PolynomialStiffness>(s.integer_rows.at("exponents")), {}};
       }},
      {"power_damper",
       "f = coefficient |d'|^exponent sign(d')",
       true,
       {},
       {},
       [](const ElementSetup&) {
         return ElementBuild{std::make_shared<PowerDamper>(),
                             {{"coefficient", "F (s/L)^exponent", Range::any, {}, "damping coefficient c"},
                              {"exponent", "1", Range::at_least_one, 2.0, "velocity exponent",
                               "the force derivative is unbounded at zero velocity below 1"}}};
       }},
      {"elastic_dry_friction",
       "Jenkins element: a spring in series with a Coulomb slider, exact periodic stick-slip",
       true,
       {},
       {},
       [](const ElementSetup&) {
         return ElementBuild{std::make_shared<ElasticDryFriction>(),
                             {stiffness("stiffness", "stiffness of the spring in series with the slider"),
                              {"limit_force", "F", Range::nonnegative, {}, "slip force of the slider"}}};
       }},
      {"elastic_dry_friction_2d",
       "Jenkins element slipping in a plane: a spring in series with a Coulomb slider of radial return",
       true,
       {},
       {},
       [](const ElementSetup&) {
         return ElementBuild{std::make_shared<ElasticDryFriction2D>(),
                             {stiffness("stiffness", "stiffness of the spring in series with the slider"),
                              {"limit_force", "F", Range::nonnegative, {}, "slip force of the slider (mu N)"}}};
       },
       2},
      {"frictional_contact",
       "normal contact with a Jenkins slider of limit mu N(t) on the tangential dof",
       false,
       {"normal", "tangential"},
       {{"law",
         ElementKey::Kind::choice,
         {"penalty", "dlft"},
         "penalty",
         0,
         0,
         "",
         "",
         "penalty contact and slider, or dlft (rigid contact and stick, Lagrange multipliers)"}},
       frictional_contact},
      {"frictional_contact_2d",
       "normal contact with a Jenkins slider of limit mu N(t) slipping in the tangential plane",
       false,
       {"normal", "tangential_1", "tangential_2"},
       {},
       [](const ElementSetup&) {
         return ElementBuild{std::make_shared<FrictionalContact>(ContactFormulation::penalty, 2),
                             {stiffness("normal_stiffness", "normal penalty stiffness k_n"),
                              stiffness("tangential_stiffness", "stiffness k_t of the Jenkins slider"),
                              mu(),
                              {"normal_preload", "F", Range::any, 0.0, "normal force at x_n = 0: N = max(0, preload + k_n x_n)"}}};
       }},
      {"iwan",
       "Segalman's four-parameter Iwan joint: parallel Jenkins sliders with a power-law density",
       true,
       {},
       // Each slider costs a pass over the samples; beyond 1000 the discretisation error (second
       // order in the grid ratio) is far below any identified joint's.
       {{"sliders",
         ElementKey::Kind::integer,
         {},
         std::to_string(Iwan::kDefaultSliders),
         2,
         1000,
         "",
         "",
         "number of discrete sliders (not bindable)"}},
       [](const ElementSetup& s) {
         return ElementBuild{
             std::make_shared<Iwan>(s.integers.at("sliders")),
             {{"limit_force", "F", Range::positive, {}, "macro-slip force F_S"},
              stiffness("stiffness", "stuck stiffness K_T"),
              {"chi",
               "1",
               Range::above_minus_one,
               {},
               "exponent of the slip-length density (micro-slip dissipation)",
               "the slider density phi^chi is not integrable at 0 otherwise"},
              {"beta", "1", Range::nonnegative, {}, "weight of the Dirac in the slip-length density: S = K_T beta / (1 + beta)"}}};
       }},
      {"tip_contact",
       "blade-tip/casing contact with friction, rotation speed engine_order omega + rotation_speed",
       false,
       {"radial", "circumferential", "axial"},
       {kContactLaw,
        {"friction",
         ElementKey::Kind::choice,
         {"sliding", "stick_slip"},
         "sliding",
         0,
         0,
         "",
         "",
         "permanent sliding, or a stick-slip slider carried by the casing"}},
       tip_contact},
  };
}

}  // namespace

const std::vector<ElementType>& element_catalog() {
  static const std::vector<ElementType> catalog = make_catalog();
  return catalog;
}

const ElementType* find_element_type(const std::string& type) {
  for (const ElementType& t : element_catalog())
    if (t.type == type) return &t;
  return nullptr;
}

std::vector<ElementSetup> element_variants(const ElementType& type) {
  std::vector<ElementSetup> variants(1);
  for (const ElementKey& key : type.keys) {
    if (key.kind == ElementKey::Kind::integer)
      for (ElementSetup& v : variants) v.integers[key.name] = std::stoi(key.fallback);
    if (key.kind == ElementKey::Kind::integer_rows)
      for (ElementSetup& v : variants) v.integer_rows[key.name] = Eigen::MatrixXi::Ones(1, 1);
    if (key.kind != ElementKey::Kind::choice) continue;
    std::vector<ElementSetup> more;
    for (const ElementSetup& v : variants)
      for (const std::string& value : key.values) {
        more.push_back(v);
        more.back().choices[key.name] = value;
      }
    variants = std::move(more);
  }
  return variants;
}

}  // namespace hbtrack
