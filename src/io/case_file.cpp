#include "hbtrack/io/case_file.hpp"

#include <toml.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "hbtrack/elements/elastic_dry_friction.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/polynomial_elements.hpp"
#include "hbtrack/elements/scalar_elements.hpp"
#include "hbtrack/elements/tip_contact.hpp"
#include "hbtrack/io/input_file.hpp"
#include "hbtrack/io/matrix_readers.hpp"
#include "hbtrack/model/damping.hpp"
#include "utf8_validation.hpp"

namespace hbtrack {

namespace {

namespace fs = std::filesystem;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr int kMaxChainCount = 4000;

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  return best_d <= std::max<size_t>(2, word.size() / 3) ? best : "";
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// Reads one case file, keeping the file name and field path for every error message.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const toml::value* where, const std::string& field, const std::string& rule) const {
    std::string loc = file_;
    if (where) {
      const auto l = where->location();
      if (l.line() > 0 && l.file_name() != "unknown file" && l.file_name() != "--set") loc += ":" + std::to_string(l.line());
      if (l.file_name() == "--set") loc = "--set";
    }
    throw CaseError(loc + ": " + (field.empty() ? "" : field + ": ") + rule);
  }

  const toml::value* find(const toml::value& table, const std::string& key) const {
    if (!table.is_table() || !table.contains(key)) return nullptr;
    return &table.at(key);
  }
  const toml::value& require(const toml::value& table, const std::string& key, const std::string& field) const {
    const toml::value* v = find(table, key);
    if (!v) fail(&table, field, "missing (required)");
    return *v;
  }
  const toml::value& table(const toml::value& v, const std::string& field) const {
    if (!v.is_table()) fail(&v, field, "expected a table");
    return v;
  }
  void check_keys(const toml::value& table_value, const std::string& field, const std::vector<std::string>& allowed) const {
    for (const auto& [key, value] : table_value.as_table()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      const std::string guess = nearest(key, allowed);
      fail(&value, field.empty() ? key : field + "." + key,
           "unknown key" + (guess.empty() ? " (expected one of: " + join(allowed) + ")" : " (did you mean '" + guess + "'?)"));
    }
  }
  double number(const toml::value& v, const std::string& field) const {
    double x = 0;
    if (v.is_integer()) x = static_cast<double>(v.as_integer());
    else if (v.is_floating()) x = v.as_floating();
    else fail(&v, field, "expected a number");
    if (!std::isfinite(x)) fail(&v, field, "must be finite");
    return x;
  }
  int integer(const toml::value& v, const std::string& field) const {
    if (!v.is_integer()) fail(&v, field, "expected an integer");
    const auto i = v.as_integer();
    if (i < -2147483647 || i > 2147483647) fail(&v, field, "integer out of range");
    return static_cast<int>(i);
  }
  std::string string(const toml::value& v, const std::string& field) const {
    if (!v.is_string()) fail(&v, field, "expected a string");
    return v.as_string().str;
  }
  double number_or(const toml::value& t, const std::string& key, const std::string& field, double fallback) const {
    const toml::value* v = find(t, key);
    return v ? number(*v, field) : fallback;
  }
  int integer_or(const toml::value& t, const std::string& key, const std::string& field, int fallback) const {
    const toml::value* v = find(t, key);
    return v ? integer(*v, field) : fallback;
  }
  std::string string_or(const toml::value& t, const std::string& key, const std::string& field, std::string fallback) const {
    const toml::value* v = find(t, key);
    return v ? string(*v, field) : fallback;
  }
  VectorXd vector(const toml::value& v, const std::string& field) const {
    if (!v.is_array()) fail(&v, field, "expected an array of numbers");
    const auto& a = v.as_array();
    VectorXd out(static_cast<Eigen::Index>(a.size()));
    for (size_t i = 0; i < a.size(); ++i) out(static_cast<Eigen::Index>(i)) = number(a[i], field + "[" + std::to_string(i) + "]");
    return out;
  }
  std::vector<std::string> strings(const toml::value& v, const std::string& field) const {
    if (v.is_string()) return {v.as_string().str};
    if (!v.is_array()) fail(&v, field, "expected a string or an array of strings");
    std::vector<std::string> out;
    for (size_t i = 0; i < v.as_array().size(); ++i) out.push_back(string(v.as_array()[i], field + "[" + std::to_string(i) + "]"));
    return out;
  }
  fs::path resolve(const std::string& relative) const {
    const fs::path p(relative);
    return p.is_absolute() ? p : fs::path(file_).parent_path() / p;
  }

  // A matrix: inline rows, {diagonal = [...]}, {file = "K.mtx"} or {file = "m.mat", variable = "K"}.
  MatrixXd matrix(const toml::value& v, const std::string& field, int n) const {
    MatrixXd m;
    if (v.is_array()) {
      const auto& rows = v.as_array();
      if (rows.empty()) fail(&v, field, "empty matrix");
      for (size_t i = 0; i < rows.size(); ++i) {
        const VectorXd row = vector(rows[i], field + "[" + std::to_string(i) + "]");
        if (i == 0) m.resize(static_cast<Eigen::Index>(rows.size()), row.size());
        if (row.size() != m.cols())
          fail(&rows[i], field, "row " + std::to_string(i) + " has " + std::to_string(row.size()) + " entries, row 0 has " + std::to_string(m.cols()));
        m.row(static_cast<Eigen::Index>(i)) = row.transpose();
      }
    } else if (v.is_table()) {
      check_keys(v, field, {"file", "variable", "diagonal"});
      if (const toml::value* d = find(v, "diagonal")) {
        m = vector(*d, field + ".diagonal").asDiagonal();
      } else if (const toml::value* f = find(v, "file")) {
        const fs::path path = resolve(string(*f, field + ".file"));
        if (!fs::exists(path)) fail(f, field + ".file", "file '" + path.string() + "' does not exist");
        // A directory, a device (/dev/zero never ends) or a pipe is not a matrix file.
        if (!fs::is_regular_file(path)) fail(f, field + ".file", "'" + path.string() + "' is not a regular file");
        try {
          if (path.extension() == ".mat") {
            const toml::value* var = find(v, "variable");
            if (!var) fail(&v, field + ".variable", "missing (required for a .mat file)");
            m = read_mat_variable(path.string(), string(*var, field + ".variable"));
          } else {
            m = read_matrix_market(path.string());
          }
        } catch (const std::runtime_error& e) {
          fail(f, field + ".file", e.what());
        }
      } else {
        fail(&v, field, "a matrix table needs 'file' or 'diagonal'");
      }
    } else {
      fail(&v, field, "expected an array of rows or a table {file = ...} / {diagonal = [...]}");
    }
    if (n >= 0 && (m.rows() != n || m.cols() != n))
      fail(&v, field, "expected " + std::to_string(n) + "x" + std::to_string(n) + " (one row per dof), got " +
                          std::to_string(m.rows()) + "x" + std::to_string(m.cols()));
    if (!m.allFinite()) fail(&v, field, "contains NaN or Inf");
    return m;
  }

 private:
  std::string file_;
};

void read_model(const Reader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value& model = in.table(in.require(root, "model", "model"), "model");
  in.check_keys(model, "model", {"dofs", "M", "K", "chain"});
  StructuralModel& m = c.model;
  if (const toml::value* chain = in.find(model, "chain")) {
    // A fixed-free chain of equal masses and springs, dofs x1..xn (x1 next to the ground).
    in.table(*chain, "model.chain");
    in.check_keys(*chain, "model.chain", {"count", "mass", "stiffness"});
    const int n = in.integer(in.require(*chain, "count", "model.chain.count"), "model.chain.count");
    // The model's matrices are dense: 4000 dofs already take 128 MB each.
    if (n < 1 || n > kMaxChainCount) in.fail(chain, "model.chain.count", "must be in [1, " + std::to_string(kMaxChainCount) + "]");
    const double mass = in.number_or(*chain, "mass", "model.chain.mass", 1.0);
    const double k = in.number_or(*chain, "stiffness", "model.chain.stiffness", 1.0);
    if (mass <= 0) in.fail(chain, "model.chain.mass", "must be > 0");
    if (k <= 0) in.fail(chain, "model.chain.stiffness", "must be > 0");
    for (int i = 1; i <= n; ++i) m.dof_names.push_back("x" + std::to_string(i));
    m.mass = mass * MatrixXd::Identity(n, n);
    m.stiffness = MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      m.stiffness(i, i) += k;  // the spring below mass i (to the ground for i = 0)
      if (i > 0) {
        m.stiffness(i - 1, i - 1) += k;
        m.stiffness(i - 1, i) -= k;
        m.stiffness(i, i - 1) -= k;
      }
    }
    if (in.find(model, "M") || in.find(model, "K") || in.find(model, "dofs"))
      in.fail(chain, "model.chain", "cannot be combined with M, K or dofs");
    return;
  }
  m.dof_names = in.strings(in.require(model, "dofs", "model.dofs"), "model.dofs");
  const int n = static_cast<int>(m.dof_names.size());
  if (n == 0) in.fail(&model.at("dofs"), "model.dofs", "needs at least one dof name");
  std::set<std::string> seen;
  for (const auto& name : m.dof_names)
    if (!seen.insert(name).second) in.fail(&model.at("dofs"), "model.dofs", "dof name '" + name + "' appears twice");
  m.mass = in.matrix(in.require(model, "M", "model.M"), "model.M", n);
  m.stiffness = in.matrix(in.require(model, "K", "model.K"), "model.K", n);
}

void read_damping(const Reader& in, const toml::value& root, CaseDefinition& c) {
  StructuralModel& m = c.model;
  const int n = m.dofs();
  const toml::value* damping = in.find(root, "damping");
  if (!damping) {
    m.damping = MatrixXd::Zero(n, n);
    return;
  }
  in.table(*damping, "damping");
  in.check_keys(*damping, "damping", {"C", "rayleigh", "modal_ratios"});
  const int given = (in.find(*damping, "C") ? 1 : 0) + (in.find(*damping, "rayleigh") ? 1 : 0) + (in.find(*damping, "modal_ratios") ? 1 : 0);
  if (given != 1) in.fail(damping, "damping", "give exactly one of C, rayleigh, modal_ratios");
  if (const toml::value* cm = in.find(*damping, "C")) {
    m.damping = in.matrix(*cm, "damping.C", n);
  } else if (const toml::value* r = in.find(*damping, "rayleigh")) {
    const VectorXd ab = in.vector(*r, "damping.rayleigh");
    if (ab.size() != 2) in.fail(r, "damping.rayleigh", "expected [alpha, beta] (C = alpha M + beta K)");
    m.damping = rayleigh_damping(m.mass, m.stiffness, ab(0), ab(1));
  } else {
    const toml::value* z = in.find(*damping, "modal_ratios");
    const VectorXd ratios = in.vector(*z, "damping.modal_ratios");
    if (ratios.size() == 0) in.fail(z, "damping.modal_ratios", "needs at least one ratio");
    if (ratios.minCoeff() < 0) in.fail(z, "damping.modal_ratios", "ratios must be >= 0");
    try {
      m.damping = modal_damping(m.mass, m.stiffness, ratios);
    } catch (const std::exception& e) {
      in.fail(z, "damping.modal_ratios", e.what());
    }
  }
}

int dof_index(const Reader& in, const StructuralModel& m, const toml::value& v, const std::string& field) {
  const std::string name = in.string(v, field);
  const int i = m.find_dof(name);
  if (i < 0) {
    const std::string guess = nearest(name, m.dof_names);
    in.fail(&v, field, "unknown dof '" + name + "'" + (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
  }
  return i;
}

void read_forcing(const Reader& in, const toml::value& root, CaseDefinition& c) {
  StructuralModel& m = c.model;
  const int n = m.dofs();
  const toml::value* forcing = in.find(root, "forcing");
  if (!forcing) return;
  if (!forcing->is_array()) in.fail(forcing, "forcing", "expected an array of tables ([[forcing]])");
  for (size_t i = 0; i < forcing->as_array().size(); ++i) {
    const std::string field = "forcing[" + std::to_string(i) + "]";
    const toml::value& f = in.table(forcing->as_array()[i], field);
    in.check_keys(f, field, {"harmonic", "dof", "cos", "sin", "shape", "mode", "scale"});
    HarmonicForce h;
    h.order = in.integer_or(f, "harmonic", field + ".harmonic", 1);
    if (h.order < 0) in.fail(&f.at("harmonic"), field + ".harmonic", "must be >= 0");
    h.cos_part = VectorXd::Zero(n);
    h.sin_part = VectorXd::Zero(n);
    if (const toml::value* shape = in.find(f, "shape")) {
      // scale * M phi_mode cos(h w t), phi mass-normalised with its largest entry positive.
      if (in.string(*shape, field + ".shape") != "mass_mode") in.fail(shape, field + ".shape", "must be \"mass_mode\"");
      if (in.find(f, "dof") || in.find(f, "cos") || in.find(f, "sin")) in.fail(shape, field + ".shape", "cannot be combined with dof, cos or sin");
      const int mode = in.integer(in.require(f, "mode", field + ".mode"), field + ".mode");
      if (mode < 1 || mode > n) in.fail(&f.at("mode"), field + ".mode", "must be in [1, " + std::to_string(n) + "] (1 is the lowest mode)");
      const NormalModes modes = normal_modes(m.mass, m.stiffness);
      VectorXd phi = modes.shapes.col(mode - 1);
      Eigen::Index largest;
      phi.cwiseAbs().maxCoeff(&largest);
      if (phi(largest) < 0) phi = -phi;
      h.cos_part = in.number_or(f, "scale", field + ".scale", 1.0) * (m.mass * phi);
      m.forcing.push_back(std::move(h));
      continue;
    }
    if (in.find(f, "mode") || in.find(f, "scale")) in.fail(&f, field, "mode and scale go with shape = \"mass_mode\"");
    if (const toml::value* dof = in.find(f, "dof")) {
      const int d = dof_index(in, m, *dof, field + ".dof");
      h.cos_part(d) = in.number_or(f, "cos", field + ".cos", 0.0);
      h.sin_part(d) = in.number_or(f, "sin", field + ".sin", 0.0);
    } else {
      for (const char* part : {"cos", "sin"}) {
        const toml::value* v = in.find(f, part);
        if (!v) continue;
        const VectorXd values = in.vector(*v, field + "." + part);
        if (values.size() != n)
          in.fail(v, field + "." + part, "expected " + std::to_string(n) + " entries (one per dof), got " + std::to_string(values.size()));
        (std::string(part) == "cos" ? h.cos_part : h.sin_part) = values;
      }
    }
    if (!in.find(f, "cos") && !in.find(f, "sin")) in.fail(&f, field, "needs cos and/or sin");
    m.forcing.push_back(std::move(h));
  }
}

void read_parameters(const Reader& in, const toml::value& root, CaseDefinition& c) {
  if (const toml::value* p = in.find(root, "parameters")) {
    in.table(*p, "parameters");
    // Sorted for a stable order in outputs.
    std::map<std::string, const toml::value*> sorted;
    for (const auto& [key, value] : p->as_table()) sorted[key] = &value;
    for (const auto& [key, value] : sorted) c.parameters.set(key, in.number(*value, "parameters." + key));
  }
  if (c.parameters.find("amplitude") < 0) c.parameters.set("amplitude", 1.0);
}

// A property: a number, a parameter name, or {parameter = "mu", scale = 1, offset = 0}.
ParameterBinding binding(const Reader& in, const CaseDefinition& c, const toml::value& v, const std::string& field) {
  auto linked = [&](const toml::value& name_value, double scale, double offset) {
    const std::string name = in.string(name_value, field);
    const int index = c.parameters.find(name);
    if (index < 0) {
      const std::string guess = nearest(name, c.parameters.names());
      in.fail(&name_value, field, "unknown parameter '" + name + "'" + (guess.empty() ? " (declare it in [parameters])" : " (did you mean '" + guess + "'?)"));
    }
    return ParameterBinding::linked(index, scale, offset);
  };
  if (v.is_string()) return linked(v, 1.0, 0.0);
  if (v.is_table()) {
    in.check_keys(v, field, {"parameter", "scale", "offset"});
    return linked(in.require(v, "parameter", field + ".parameter"), in.number_or(v, "scale", field + ".scale", 1.0),
                  in.number_or(v, "offset", field + ".offset", 0.0));
  }
  return ParameterBinding::constant(in.number(v, field));
}

struct PropertySpec {
  std::string name;
  bool required;
  double fallback;
};

// polynomial_stiffness: `exponents` (one row of nonnegative integers per monomial) now, its
// `coefficients` (same rows, one bindable entry per dof) once the dofs are known.
std::shared_ptr<PolynomialStiffness> read_polynomial_exponents(const Reader& in, const toml::value& e, const std::string& field) {
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

void read_polynomial_coefficients(const Reader& in, const toml::value& e, const std::string& field, CaseDefinition& c,
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

void read_elements(const Reader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* elements = in.find(root, "elements");
  if (!elements) return;
  if (!elements->is_array()) in.fail(elements, "elements", "expected an array of tables ([[elements]])");
  const std::vector<std::string> types{"cubic_spring",         "unilateral_spring", "regularized_contact", "tanh_friction", "tip_contact",
                                       "polynomial_stiffness", "power_damper",      "elastic_dry_friction", "frictional_contact"};
  for (size_t i = 0; i < elements->as_array().size(); ++i) {
    const std::string field = "elements[" + std::to_string(i) + "]";
    const toml::value& e = in.table(elements->as_array()[i], field);
    const toml::value& type_value = in.require(e, "type", field + ".type");
    const std::string type = in.string(type_value, field + ".type");
    std::shared_ptr<NonlinearElement> element;
    std::vector<PropertySpec> specs;
    ContactLawKind law = ContactLawKind::polynomial;
    if (const toml::value* l = in.find(e, "law")) {
      try {
        law = parse_contact_law(in.string(*l, field + ".law"));
      } catch (const std::invalid_argument& err) {
        in.fail(l, field + ".law", err.what());
      }
    }
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
      element = std::make_shared<TipContact>(law);
      specs = {{"stiffness", true, 0}, {"clearance", true, 0}, {"width", true, 0}, {"mu", true, 0},
               {"radius", true, 0},    {"engine_order", false, 1.0}, {"rotation_speed", false, 0.0}};
    } else if (type == "polynomial_stiffness") {
      element = read_polynomial_exponents(in, e, field);
    } else if (type == "power_damper") {
      element = std::make_shared<PowerDamper>();
      specs = {{"coefficient", true, 0}, {"exponent", false, 2.0}};
    } else if (type == "elastic_dry_friction") {
      element = std::make_shared<ElasticDryFriction>();
      specs = {{"stiffness", true, 0}, {"limit_force", true, 0}};
    } else if (type == "frictional_contact") {
      element = std::make_shared<FrictionalContact>();
      specs = {{"normal_stiffness", true, 0}, {"tangential_stiffness", true, 0}, {"mu", true, 0}, {"normal_preload", false, 0.0}};
    } else {
      const std::string guess = nearest(type, types);
      in.fail(&type_value, field + ".type", "unknown element type '" + type + "'" +
                                                 (guess.empty() ? " (expected one of: " + join(types) + ")" : " (did you mean '" + guess + "'?)"));
    }
    std::vector<std::string> allowed{"type", "dofs", "lanczos"};
    if (type == "regularized_contact" || type == "tip_contact") allowed.push_back("law");
    const bool polynomial = type == "polynomial_stiffness";
    const bool scalar = type != "tip_contact" && type != "frictional_contact" && !polynomial;
    if (scalar) allowed.push_back("weights");
    if (polynomial) allowed.insert(allowed.end(), {"exponents", "coefficients"});
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
      const bool must_be_positive = name == "stiffness" || name == "normal_stiffness" || name == "tangential_stiffness" || name == "regularization_velocity" ||
                                    (name == "width" && type != "unilateral_spring") || name == "radius";
      // The sign of engine_order is the sense of rotation (rotor 67 and the parametric blade
      // turn towards -theta of their tip frames); 0 would stop the rotor.
      const bool must_be_nonzero = name == "engine_order";
      const bool must_be_nonnegative = name == "mu" || name == "normal_load" || name == "clearance" || name == "limit_force";
      const toml::value* v = in.find(e, name);
      if (must_be_positive && !(values[p] > 0)) in.fail(v ? v : &e, field + "." + name, "must be > 0");
      if (must_be_nonzero && !(values[p] != 0)) in.fail(v ? v : &e, field + "." + name, "must be nonzero (its sign is the sense of rotation)");
      if (must_be_nonnegative && values[p] < 0) in.fail(v ? v : &e, field + "." + name, "must be >= 0");
      if (name == "exponent" && !(values[p] >= 1)) in.fail(v ? v : &e, field + "." + name, "must be >= 1 (the force derivative is unbounded at zero velocity below 1)");
    }
    element->lanczos_exponent = in.number_or(e, "lanczos", field + ".lanczos", 0.0);
    if (element->lanczos_exponent < 0) in.fail(&e.at("lanczos"), field + ".lanczos", "must be >= 0 (0 disables the filter)");
    // sinc(j/(H+1))^p: beyond p = 10 the higher harmonics of the force vanish (1e9 removed them all).
    if (element->lanczos_exponent > 10) in.fail(&e.at("lanczos"), field + ".lanczos", "must be <= 10");
    c.elements.push_back(std::move(element));
  }
}

void read_settings(const Reader& in, const toml::value& root, CaseDefinition& c) {
  if (const toml::value* h = in.find(root, "harmonic_balance")) {
    in.table(*h, "harmonic_balance");
    in.check_keys(*h, "harmonic_balance", {"harmonics", "samples", "condensation"});
    c.harmonic_balance.harmonics = in.integer_or(*h, "harmonics", "harmonic_balance.harmonics", c.harmonic_balance.harmonics);
    c.harmonic_balance.samples = in.integer_or(*h, "samples", "harmonic_balance.samples", 0);
    c.harmonic_balance.condensation = in.string_or(*h, "condensation", "harmonic_balance.condensation", "auto");
    try {
      c.harmonic_balance.validate();
    } catch (const std::invalid_argument& e) {
      in.fail(h, "", e.what());
    }
  }
  const toml::value& cont = in.table(in.require(root, "continuation", "continuation"), "continuation");
  in.check_keys(cont, "continuation",
                {"omega_start", "omega_end", "length_scale", "step", "step_min", "step_max", "max_points", "max_iterations",
                 "target_iterations", "tolerance", "max_angle", "predictor", "corrector", "wall_time_limit", "locate",
                 "reuse_factorization", "contraction"});
  NfrcOptions& o = c.nfrc;
  ContinuationOptions& co = o.continuation;
  o.omega_start = in.number(in.require(cont, "omega_start", "continuation.omega_start"), "continuation.omega_start");
  o.omega_end = in.number(in.require(cont, "omega_end", "continuation.omega_end"), "continuation.omega_end");
  o.length_scale = in.number_or(cont, "length_scale", "continuation.length_scale", 0.0);
  co.step = in.number_or(cont, "step", "continuation.step", co.step);
  co.step_min = in.number_or(cont, "step_min", "continuation.step_min", std::min(co.step_min, co.step));
  co.step_max = in.number_or(cont, "step_max", "continuation.step_max", std::max(co.step_max, co.step));
  co.max_points = in.integer_or(cont, "max_points", "continuation.max_points", co.max_points);
  co.max_iterations = in.integer_or(cont, "max_iterations", "continuation.max_iterations", co.max_iterations);
  co.target_iterations = in.integer_or(cont, "target_iterations", "continuation.target_iterations", co.target_iterations);
  co.tolerance = in.number_or(cont, "tolerance", "continuation.tolerance", co.tolerance);
  co.max_angle = in.number_or(cont, "max_angle", "continuation.max_angle", co.max_angle);
  co.predictor = in.string_or(cont, "predictor", "continuation.predictor", co.predictor);
  co.corrector = in.string_or(cont, "corrector", "continuation.corrector", co.corrector);
  co.wall_time_limit = in.number_or(cont, "wall_time_limit", "continuation.wall_time_limit", co.wall_time_limit);
  if (const toml::value* locate = in.find(cont, "locate")) {
    if (!locate->is_boolean()) in.fail(locate, "continuation.locate", "expected true or false");
    co.locate = locate->as_boolean();
  }
  if (const toml::value* reuse = in.find(cont, "reuse_factorization")) {
    if (!reuse->is_boolean()) in.fail(reuse, "continuation.reuse_factorization", "expected true or false");
    co.reuse_factorization = reuse->as_boolean();
  }
  co.contraction = in.number_or(cont, "contraction", "continuation.contraction", co.contraction);
  if (const toml::value* st = in.find(root, "stability")) {
    in.table(*st, "stability");
    in.check_keys(*st, "stability", {"method", "monodromy_steps", "hill_solver", "cross_check"});
    o.stability.cross_check = in.string_or(*st, "cross_check", "stability.cross_check", o.stability.cross_check);
    o.stability.hill_solver = in.string_or(*st, "hill_solver", "stability.hill_solver", o.stability.hill_solver);
    o.stability.method = in.string_or(*st, "method", "stability.method", o.stability.method);
    o.stability.monodromy_steps = in.integer_or(*st, "monodromy_steps", "stability.monodromy_steps", o.stability.monodromy_steps);
  }
  try {
    o.validate();
  } catch (const std::invalid_argument& e) {
    // The message already names the field.
    in.fail(&cont, "", e.what());
  }
  // Relative to the force scale: at 1 the zero response already passes for a solution.
  if (co.tolerance >= 1) in.fail(in.find(cont, "tolerance"), "continuation.tolerance", "must be < 1 (it is relative to the forcing)");
}

// A forcing harmonic above the truncation would silently vanish from the balance.
void check_forcing_within_harmonics(const Reader& in, const toml::value& root, const CaseDefinition& c) {
  const toml::value* forcing = in.find(root, "forcing");
  const int harmonics = c.harmonic_balance.harmonics;
  for (size_t i = 0; forcing && i < forcing->as_array().size(); ++i) {
    const toml::value& f = forcing->as_array()[i];
    const std::string field = "forcing[" + std::to_string(i) + "].harmonic";
    if (in.integer_or(f, "harmonic", field, 1) > harmonics)
      in.fail(&f.at("harmonic"), field, "must be <= harmonic_balance.harmonics = " + std::to_string(harmonics) + " (a higher harmonic is not represented)");
  }
}

void read_outputs(const Reader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* outputs = in.find(root, "outputs");
  if (!outputs) return;
  if (!outputs->is_array()) in.fail(outputs, "outputs", "expected an array of tables ([[outputs]])");
  std::set<std::string> names;
  for (size_t i = 0; i < outputs->as_array().size(); ++i) {
    const std::string field = "outputs[" + std::to_string(i) + "]";
    const toml::value& o = in.table(outputs->as_array()[i], field);
    in.check_keys(o, field, {"name", "dof"});
    OutputDof out;
    out.dof = dof_index(in, c.model, in.require(o, "dof", field + ".dof"), field + ".dof");
    out.name = in.string_or(o, "name", field + ".name", c.model.dof_names[static_cast<size_t>(out.dof)]);
    if (out.name.empty() || out.name.find_first_of(",\"\n ") != std::string::npos)
      in.fail(&o, field + ".name", "must be non-empty without commas, quotes or spaces (it names CSV columns)");
    if (!names.insert(out.name).second) in.fail(&o, field + ".name", "output name '" + out.name + "' appears twice");
    c.outputs.push_back(out);
  }
}

void read_study(const Reader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* st = in.find(root, "study");
  if (!st) return;
  in.table(*st, "study");
  in.check_keys(*st, "study", {"track", "max_points", "simulate_periods", "convergence"});
  StudySettings& study = c.study;
  study.max_points = in.integer_or(*st, "max_points", "study.max_points", study.max_points);
  if (study.max_points < 2) in.fail(&st->at("max_points"), "study.max_points", "must be >= 2");
  study.simulate_periods = in.integer_or(*st, "simulate_periods", "study.simulate_periods", study.simulate_periods);
  if (study.simulate_periods < 0) in.fail(&st->at("simulate_periods"), "study.simulate_periods", "must be >= 0");
  if (const toml::value* conv = in.find(*st, "convergence")) {
    in.table(*conv, "study.convergence");
    in.check_keys(*conv, "study.convergence", {"harmonics", "samples"});
    study.convergence_harmonics = in.integer_or(*conv, "harmonics", "study.convergence.harmonics", 0);
    study.convergence_samples = in.integer_or(*conv, "samples", "study.convergence.samples", 0);
    // harmonics = 0 turns the check off (e.g. with --set study.convergence.harmonics=0).
    if (study.convergence_harmonics < 0 || (study.convergence_harmonics > 0 && study.convergence_samples < 2 * study.convergence_harmonics + 1))
      in.fail(conv, "study.convergence", "expected {harmonics = H >= 1, samples = N >= 2 H + 1} (H = 0: no check)");
  }
  const toml::value* track = in.find(*st, "track");
  if (!track) return;
  if (!track->is_array()) in.fail(track, "study.track", "expected an array of tables {parameter = ..., range = [lo, hi]}");
  for (size_t i = 0; i < track->as_array().size(); ++i) {
    const std::string field = "study.track[" + std::to_string(i) + "]";
    const toml::value& t = in.table(track->as_array()[i], field);
    in.check_keys(t, field, {"parameter", "range", "validate"});
    StudyTrack s;
    const toml::value& name = in.require(t, "parameter", field + ".parameter");
    s.parameter = in.string(name, field + ".parameter");
    if (c.parameters.find(s.parameter) < 0) {
      const std::string guess = nearest(s.parameter, c.parameters.names());
      in.fail(&name, field + ".parameter", "unknown parameter '" + s.parameter + "'" + (guess.empty() ? " (declare it in [parameters])" : " (did you mean '" + guess + "'?)"));
    }
    const toml::value& range = in.require(t, "range", field + ".range");
    const VectorXd r = in.vector(range, field + ".range");
    if (r.size() != 2 || !(r(0) < r(1))) in.fail(&range, field + ".range", "expected [lo, hi] with lo < hi");
    s.min = r(0);
    s.max = r(1);
    const double value = c.parameters.value(c.parameters.find(s.parameter));
    if (!(s.min <= value && value <= s.max))
      in.fail(&range, field + ".range", "must contain the case's " + s.parameter + " = " + std::to_string(value) + " (tracking starts there)");
    if (const toml::value* validate = in.find(t, "validate")) {
      const VectorXd v = in.vector(*validate, field + ".validate");
      for (Eigen::Index k = 0; k < v.size(); ++k) {
        if (!(s.min <= v(k) && v(k) <= s.max)) in.fail(validate, field + ".validate", "every value must lie in the range");
        s.validate.push_back(v(k));
      }
    }
    for (const StudyTrack& other : study.track)
      if (other.parameter == s.parameter) in.fail(&name, field + ".parameter", "'" + s.parameter + "' is tracked twice");
    study.track.push_back(s);
  }
}

// Applies "NAME=VALUE" overrides to the parsed TOML document.
void apply_overrides(const Reader& in, toml::value& root, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0) throw CaseError("--set " + o + ": expected NAME=VALUE");
    const std::string name = o.substr(0, eq), text = o.substr(eq + 1);
    // One value only: a newline or a comment would let a second key or text after the value
    // pass unseen.
    if (text.find_first_of("\n\r") != std::string::npos) throw CaseError("--set " + name + ": the value must be on one line");
    check_toml_nesting(text, "--set " + name);
    toml::value value;
    bool parsed = false;
    try {
      std::istringstream ss("v = " + text);
      const toml::value table = toml::parse(ss, "--set");
      if (table.as_table().size() == 1) value = table.at("v"), parsed = true;
    } catch (const std::exception&) {
    }
    // A '#' outside a string starts a comment: `amplitude=1 #2` set 1 and dropped the rest.
    if (parsed) {
      std::istringstream ss("v = " + text);
      if (!toml::parse<toml::preserve_comments>(ss, "--set").at("v").comments().empty())
        throw CaseError("--set " + name + ": '" + text + "' is one value followed by a '#' comment (quote a string: " + name + "='\"...\"')");
    }
    if (!parsed) {
      if (text.find_first_of("[]{}#\"'=,") != std::string::npos)
        throw CaseError("--set " + name + ": '" + text + "' is not one TOML value (quote a string: " + name + "='\"...\"')");
      value = toml::value(text);  // an unquoted word: take it as a string
    }
    if (name.find('.') == std::string::npos) {
      // A named parameter: it must exist, so that a typo is not silently ignored.
      toml::value& params = root["parameters"];
      if (!params.is_table()) params = toml::table{};
      if (!params.contains(name) && name != "amplitude") {
        std::vector<std::string> known{"amplitude"};
        for (const auto& [k, v] : params.as_table())
          if (k != "amplitude") known.push_back(k);
        const std::string guess = nearest(name, known);
        throw CaseError("--set " + name + ": unknown parameter" + (guess.empty() ? " (known: " + join(known) + ")" : " (did you mean '" + guess + "'?)"));
      }
      if (!value.is_integer() && !value.is_floating()) throw CaseError("--set " + name + ": expected a number, got '" + text + "'");
      params[name] = value;
      continue;
    }
    // A path like harmonic_balance.harmonics or elements[0].stiffness (as errors print it).
    toml::value* node = &root;
    std::string path;
    size_t start = 0;
    while (true) {
      const size_t dot = name.find('.', start);
      std::string key = name.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      int index = -1;
      if (const size_t open = key.find('['); open != std::string::npos) {
        const size_t close = key.find(']', open);
        if (close != key.size() - 1 || close == open + 1 ||
            key.find_first_not_of("0123456789", open + 1) != close)
          throw CaseError("--set " + name + ": expected KEY or KEY[INDEX] in the path, got '" + key + "'");
        index = std::stoi(key.substr(open + 1, close - open - 1));
        key = key.substr(0, open);
      }
      path += (path.empty() ? "" : ".") + key;
      const bool last = dot == std::string::npos;
      if (last && index < 0) {
        (*node)[key] = value;
        break;
      }
      toml::value& next = (*node)[key];
      if (index >= 0) {
        if (!next.is_array()) throw CaseError("--set " + name + ": '" + path + "' is not an array");
        if (index >= static_cast<int>(next.as_array().size()))
          throw CaseError("--set " + name + ": '" + path + "' has " + std::to_string(next.as_array().size()) + " entries");
        toml::value& entry = next.as_array()[static_cast<size_t>(index)];
        if (last) {
          entry = value;
          break;
        }
        if (!entry.is_table()) throw CaseError("--set " + name + ": '" + path + "[" + std::to_string(index) + "]' is not a table");
        node = &entry;
      } else {
        if (!next.is_table()) {
          if (!next.is_uninitialized()) throw CaseError("--set " + name + ": '" + path + "' is not a table");
          next = toml::table{};
        }
        node = &next;
      }
      start = dot + 1;
    }
  }
  (void)in;
}

}  // namespace

CaseDefinition load_case(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_bounded_file(path, kMaxCaseFileBytes, "a TOML case file");
  // TOML is UTF-8. Checked here because toml11 3.7 reads out of bounds when it reports invalid
  // UTF-8 inside a string (fuzzing: a literal string holding the byte 0xE0).
  if (const std::size_t bad = first_invalid_utf8(text); bad != std::string_view::npos) {
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n');
    throw CaseError(path + ":" + std::to_string(line) + ": not valid UTF-8 (byte " + std::to_string(bad) + "); a TOML case file must be UTF-8");
  }
  check_toml_nesting(text, path);
  toml::value root;
  try {
    std::istringstream stream(text);
    root = toml::parse(stream, path);
  } catch (const toml::syntax_error& e) {
    // toml11 reports over several lines; keep the first line and the line number.
    std::string msg = e.what();
    const std::string first = msg.substr(0, msg.find('\n'));
    const std::string line = std::to_string(e.location().line());
    throw CaseError(path + ":" + line + ": TOML syntax error: " + first.substr(first.find(':') == std::string::npos ? 0 : first.find(':') + 2));
  } catch (const std::exception& e) {
    std::string msg = e.what();
    throw CaseError(path + ": cannot read: " + msg.substr(0, msg.find('\n')));
  }
  Reader in(path);
  if (!root.is_table()) throw CaseError(path + ": expected a TOML table at the top level");
  apply_overrides(in, root, overrides);
  in.check_keys(root, "", {"model", "damping", "forcing", "parameters", "elements", "harmonic_balance", "continuation", "stability", "outputs", "study"});
  CaseDefinition c;
  c.path = path;
  read_model(in, root, c);
  read_damping(in, root, c);
  read_forcing(in, root, c);
  try {
    c.model.validate();
  } catch (const std::invalid_argument& e) {
    throw CaseError(path + ": " + e.what());
  }
  read_parameters(in, root, c);
  read_elements(in, root, c);
  read_settings(in, root, c);
  check_forcing_within_harmonics(in, root, c);
  read_outputs(in, root, c);
  read_study(in, root, c);
  return c;
}

int parameter_index(const ParameterSet& parameters, const std::string& name, const std::string& field) {
  const int index = parameters.find(name);
  if (index >= 0) return index;
  std::string known;
  for (const std::string& n : parameters.names()) known += (known.empty() ? "" : ", ") + n;
  throw CaseError(field + ": unknown parameter '" + name + "' (the case has: " + known + ")");
}

}  // namespace hbtrack
