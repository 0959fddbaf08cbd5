#include "case_elements.hpp"

#include <set>

#include "hbtrack/elements/elastic_dry_friction_2d.hpp"
#include "hbtrack/elements/element_catalog.hpp"
#include "hbtrack/elements/scalar_elements.hpp"

namespace hbtrack {

using Eigen::VectorXd;

namespace {

// An integer key's value within the key's [min, max].
int bounded_integer(const CaseReader& in, const toml::value& v, const ElementKey& key, const std::string& field) {
  const int value = in.integer(v, field);
  if (value < key.min || value > key.max)
    in.fail(&v, field, "must be an integer in [" + std::to_string(key.min) + ", " + std::to_string(key.max) + "]");
  return value;
}

// An integer_rows key: one row per key.row, each of the same length (one key.entry per dof).
Eigen::MatrixXi integer_rows(const CaseReader& in, const toml::value& e, const ElementKey& key, const std::string& field) {
  const toml::value& value = in.require(e, key.name, field);
  if (!value.is_array() || value.as_array().empty()) in.fail(&value, field, "expected an array of rows, one per " + key.row);
  const auto& rows = value.as_array();
  Eigen::MatrixXi out;
  for (size_t m = 0; m < rows.size(); ++m) {
    const std::string row_field = field + "[" + std::to_string(m) + "]";
    if (!rows[m].is_array()) in.fail(&rows[m], row_field, "expected an array of integers, one per dof");
    const auto& row = rows[m].as_array();
    if (m == 0) out.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(row.size()));
    if (static_cast<Eigen::Index>(row.size()) != out.cols())
      in.fail(&rows[m], row_field, "every row needs the same length (one " + key.entry + " per dof)");
    for (size_t j = 0; j < row.size(); ++j)
      out(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(j)) =
          bounded_integer(in, row[j], key, row_field + "[" + std::to_string(j) + "]");
  }
  return out;
}

// The values of the keys that decide how the element is built (defaults where absent).
ElementSetup read_setup(const CaseReader& in, const toml::value& e, const ElementType& type, const std::string& field) {
  ElementSetup setup;
  for (const ElementKey& key : type.keys) {
    const toml::value* v = in.find(e, key.name);
    const std::string key_field = field + "." + key.name;
    switch (key.kind) {
      case ElementKey::Kind::choice:
        setup.choices[key.name] = v ? in.string(*v, key_field) : key.fallback;
        break;
      case ElementKey::Kind::integer:
        setup.integers[key.name] = v ? bounded_integer(in, *v, key, key_field) : std::stoi(key.fallback);
        break;
      case ElementKey::Kind::integer_rows:
        setup.integer_rows[key.name] = integer_rows(in, e, key, key_field);
        break;
      case ElementKey::Kind::property_rows:
        break;  // properties: read once the dofs are known
    }
  }
  return setup;
}

// A property_rows key: rows of properties (one per row of the element's integer rows), one
// bindable entry per dof, appended to the element's properties.
void read_property_rows(const CaseReader& in, const toml::value& e, const ElementKey& key, const std::string& field, CaseDefinition& c,
                        NonlinearElement& element, Eigen::Index rows) {
  const int k = element.local_dofs();
  const toml::value& value = in.require(e, key.name, field);
  if (!value.is_array() || static_cast<Eigen::Index>(value.as_array().size()) != rows)
    in.fail(&value, field, "expected one row per " + key.row + " (" + std::to_string(rows) + ")");
  for (size_t m = 0; m < value.as_array().size(); ++m) {
    const toml::value& row = value.as_array()[m];
    const std::string row_field = field + "[" + std::to_string(m) + "]";
    if (!row.is_array() || static_cast<int>(row.as_array().size()) != k)
      in.fail(&row, row_field, "expected one " + key.entry + " per dof (" + std::to_string(k) + ")");
    for (size_t i = 0; i < row.as_array().size(); ++i)
      element.properties.push_back(binding(in, c, row.as_array()[i], row_field + "[" + std::to_string(i) + "]"));
  }
}

// d = w.x: the weights given, or [1] on one dof and [1, -1] (x_a - x_b) between two.
void read_weights(const CaseReader& in, const toml::value& e, const std::string& field, ScalarElement& s) {
  const int k = s.local_dofs();
  if (const toml::value* w = in.find(e, "weights")) {
    s.weights = in.vector(*w, field + ".weights");
    if (s.weights.size() != k) in.fail(w, field + ".weights", "expected one weight per dof (" + std::to_string(k) + ")");
    if (s.weights.isZero(0.0)) in.fail(w, field + ".weights", "must not all be zero (the element would act on nothing)");
  } else if (k == 1) {
    s.weights = VectorXd::Ones(1);
  } else if (k == 2) {
    s.weights = (VectorXd(2) << 1.0, -1.0).finished();  // relative displacement x_a - x_b
  } else {
    in.fail(&e, field + ".weights", "required for more than two dofs");
  }
}

// u = W x over the plane of a slider (W 2 x k): the rows given, or the identity on [x, y] and the
// relative motion [[1, 0, -1, 0], [0, 1, 0, -1]] on [x_a, y_a, x_b, y_b].
void read_planar_weights(const CaseReader& in, const toml::value& e, const std::string& field, ElasticDryFriction2D& s) {
  const int k = s.local_dofs();
  const std::string weights_field = field + ".weights";
  const toml::value* w = in.find(e, "weights");
  if (!w) {
    if (k == 2) {
      s.weights = Eigen::MatrixXd::Identity(2, 2);
    } else if (k == 4) {
      s.weights = (Eigen::MatrixXd(2, 4) << 1.0, 0.0, -1.0, 0.0, 0.0, 1.0, 0.0, -1.0).finished();
    } else {
      in.fail(&e, weights_field, "required unless the dofs are [x, y] (2) or [x_a, y_a, x_b, y_b] (4)");
    }
    return;
  }
  if (!w->is_array() || w->as_array().size() != 2 || !w->as_array()[0].is_array() || !w->as_array()[1].is_array())
    in.fail(w, weights_field, "expected two rows, one per direction of the plane: [[w_x...], [w_y...]]");
  s.weights.resize(2, k);
  for (size_t j = 0; j < 2; ++j) {
    const toml::value& row = w->as_array()[j];
    const std::string row_field = weights_field + "[" + std::to_string(j) + "]";
    const VectorXd r = in.vector(row, row_field);
    if (r.size() != k) in.fail(&row, row_field, "expected one weight per dof (" + std::to_string(k) + ")");
    if (r.isZero(0.0)) in.fail(&row, row_field, "must not all be zero (the direction would be no direction)");
    s.weights.row(static_cast<Eigen::Index>(j)) = r.transpose();
  }
  // Gram determinant |w_x|^2 |w_y|^2 - (w_x.w_y)^2 = |w_x|^2 |w_y|^2 sin^2(angle), against round-off.
  const double xx = s.weights.row(0).squaredNorm(), yy = s.weights.row(1).squaredNorm(), xy = s.weights.row(0).dot(s.weights.row(1));
  if (xx * yy - xy * xy <= 1e-12 * xx * yy)
    in.fail(w, weights_field, "the two rows must not be parallel (the slider would slip along a line, not in a plane)");
}

std::string join_names(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

}  // namespace

void read_elements(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* elements = in.find(root, "elements");
  if (!elements) return;
  if (!elements->is_array()) in.fail(elements, "elements", "expected an array of tables ([[elements]])");
  std::vector<std::string> types;
  for (const ElementType& t : element_catalog()) types.push_back(t.type);
  for (size_t i = 0; i < elements->as_array().size(); ++i) {
    const std::string field = "elements[" + std::to_string(i) + "]";
    const toml::value& e = in.table(elements->as_array()[i], field);
    const toml::value& type_value = in.require(e, "type", field + ".type");
    const std::string type_name = in.string(type_value, field + ".type");
    const ElementType* type = find_element_type(type_name);
    if (!type) {
      const std::string guess = nearest(type_name, types);
      in.fail(&type_value, field + ".type",
              "unknown element type '" + type_name + "'" +
                  (guess.empty() ? " (expected one of: " + join(types) + ")" : " (did you mean '" + guess + "'?)"));
    }
    const ElementSetup setup = read_setup(in, e, *type, field);
    // Templates are expanded before the overrides: only `--set elements[i].nodes=...` gets here.
    if (const toml::value* nodes = in.find(e, "nodes"))
      in.fail(nodes, field + ".nodes", "templates are expanded before --set: set the expanded elements' keys instead");
    ElementBuild built;
    try {
      built = type->build(setup);
    } catch (const ElementKeyError& err) {
      in.fail(in.find(e, err.key()), field + "." + err.key(), err.what());
    }
    NonlinearElement& element = *built.element;
    const std::vector<PropertySpec>& specs = built.properties;
    std::vector<std::string> allowed{"type", "dofs", "lanczos"};
    if (type->weighted) allowed.push_back("weights");
    for (const ElementKey& key : type->keys) allowed.push_back(key.name);
    for (const PropertySpec& s : specs) allowed.push_back(s.name);
    in.check_keys(e, field, allowed);

    const toml::value& dofs_value = in.require(e, "dofs", field + ".dofs");
    if (!dofs_value.is_array() && !dofs_value.is_string()) in.fail(&dofs_value, field + ".dofs", "expected an array of dof names");
    std::vector<toml::value> dof_values = dofs_value.is_array() ? dofs_value.as_array() : std::vector<toml::value>{dofs_value};
    for (size_t d = 0; d < dof_values.size(); ++d)
      element.dofs.push_back(dof_index(in, c.model, dof_values[d], field + ".dofs[" + std::to_string(d) + "]"));
    const int k = element.local_dofs();
    const int named = static_cast<int>(type->dof_names.size());
    if (named > 0 && k != named)
      in.fail(&dofs_value, field + ".dofs",
              "expected " + std::to_string(named) + " dofs [" + join_names(type->dof_names) + "], got " + std::to_string(k));
    if (type->weighted && k < 1) in.fail(&dofs_value, field + ".dofs", "expected at least one dof");
    if (std::set<int>(element.dofs.begin(), element.dofs.end()).size() != element.dofs.size())
      in.fail(&dofs_value, field + ".dofs", "a dof appears twice");
    if (type->weighted && type->directions == 1) read_weights(in, e, field, static_cast<ScalarElement&>(element));
    if (type->weighted && type->directions == 2) read_planar_weights(in, e, field, static_cast<ElasticDryFriction2D&>(element));
    // Integer rows hold one entry per dof; property rows, one row per integer row.
    Eigen::Index rows = 0;
    for (const ElementKey& key : type->keys) {
      const std::string key_field = field + "." + key.name;
      if (key.kind == ElementKey::Kind::integer_rows) {
        const Eigen::MatrixXi& m = setup.integer_rows.at(key.name);
        if (m.cols() != k)
          in.fail(&e.at(key.name), key_field, "expected one " + key.entry + " per dof (" + std::to_string(k) + ") in each row");
        rows = m.rows();
      } else if (key.kind == ElementKey::Kind::property_rows) {
        read_property_rows(in, e, key, key_field, c, element, rows);
      }
    }
    for (const PropertySpec& spec : specs) {
      const toml::value* v = in.find(e, spec.name);
      if (!v && !spec.fallback) in.fail(&e, field + "." + spec.name, "missing (required for " + type_name + ")");
      element.properties.push_back(v ? binding(in, c, *v, field + "." + spec.name) : ParameterBinding::constant(*spec.fallback));
    }
    // Physical ranges at the nominal parameter values.
    const std::vector<double> values = element.property_values(c.parameters);
    for (size_t p = 0; p < specs.size(); ++p) {
      const PropertySpec& spec = specs[p];
      if (admits(spec.range, values[p])) continue;
      const toml::value* v = in.find(e, spec.name);
      std::string rule = spec.range == PropertyRange::nonzero ? "must be nonzero" : "must be " + to_string(spec.range);
      if (!spec.why.empty()) rule += " (" + spec.why + ")";
      in.fail(v ? v : &e, field + "." + spec.name, rule);
    }
    element.lanczos_exponent = in.number_or(e, "lanczos", field + ".lanczos", 0.0);
    if (element.lanczos_exponent < 0) in.fail(&e.at("lanczos"), field + ".lanczos", "must be >= 0 (0 disables the filter)");
    // sinc(j/(H+1))^p: beyond p = 10 the higher harmonics of the force vanish (1e9 removed them all).
    if (element.lanczos_exponent > 10) in.fail(&e.at("lanczos"), field + ".lanczos", "must be <= 10");
    c.elements.push_back(std::move(built.element));
  }
}

}  // namespace hbtrack
