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

#include "case_dof_names.hpp"
#include "case_elements.hpp"
#include "case_excitation.hpp"
#include "case_rotation.hpp"
#include "case_study.hpp"
#include "case_reader.hpp"
#include "case_templates.hpp"
#include "hbtrack/io/input_file.hpp"
#include "hbtrack/model/damping.hpp"
#include "utf8_validation.hpp"

namespace hbtrack {

namespace {

namespace fs = std::filesystem;
using Eigen::MatrixXd;
using Eigen::VectorXd;

void read_model(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value& model = in.table(in.require(root, "model", "model"), "model");
  in.check_keys(model, "model", {"dofs", "M", "K", "chain", "Kg1", "Mspin", "G"});
  StructuralModel& m = c.model;
  if (const toml::value* chain = in.find(model, "chain")) {
    // A fixed-free chain of equal masses and springs, dofs x1..xn (x1 next to the ground).
    in.table(*chain, "model.chain");
    in.check_keys(*chain, "model.chain", {"count", "mass", "stiffness"});
    const int n = in.integer(in.require(*chain, "count", "model.chain.count"), "model.chain.count");
    if (n < 1 || n > kMaxModelDofs) in.fail(chain, "model.chain.count", "must be in [1, " + std::to_string(kMaxModelDofs) + "]");
    const double mass = in.number_or(*chain, "mass", "model.chain.mass", 1.0);
    const double k = in.number_or(*chain, "stiffness", "model.chain.stiffness", 1.0);
    if (mass <= 0) in.fail(chain, "model.chain.mass", "must be > 0");
    if (k <= 0) in.fail(chain, "model.chain.stiffness", "must be > 0");
    m.dof_names = numbered_dof_names(n);
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
  const toml::value& dofs = in.require(model, "dofs", "model.dofs");
  // `dofs = N`: names x1 .. xN, as the chain's; generated once M and K are known to be N x N.
  const bool counted = dofs.is_integer();
  // Bounded before any matrix is read: a dense model beyond it exhausts memory (kMaxModelDofs).
  const std::string why = ": the model's matrices are dense (reduce a larger model first: hbtrack reduce)";
  if (counted && (in.integer(dofs, "model.dofs") < 1 || in.integer(dofs, "model.dofs") > kMaxModelDofs))
    in.fail(&dofs, "model.dofs", "must be in [1, " + std::to_string(kMaxModelDofs) + "] (the number of dofs, named x1 .. xN)" + why);
  if (!counted) m.dof_names = read_dof_names(in, dofs, "model.dofs");
  if (m.dof_names.size() > static_cast<size_t>(kMaxModelDofs))
    in.fail(&dofs, "model.dofs", std::to_string(m.dof_names.size()) + " names, at most " + std::to_string(kMaxModelDofs) + why);
  if (const toml::value* file = dofs.is_table() ? in.find(dofs, "file") : nullptr)
    c.dofs_file = in.resolve(in.string(*file, "model.dofs.file")).string();
  const int n = counted ? in.integer(dofs, "model.dofs") : static_cast<int>(m.dof_names.size());
  m.mass = in.matrix(in.require(model, "M", "model.M"), "model.M", n);
  m.stiffness = in.matrix(in.require(model, "K", "model.K"), "model.K", n);
  if (counted) m.dof_names = numbered_dof_names(n);
}

void read_damping(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  StructuralModel& m = c.model;
  const int n = m.dofs();
  const toml::value* damping = in.find(root, "damping");
  if (!damping) {
    m.damping = MatrixXd::Zero(n, n);
    return;
  }
  in.table(*damping, "damping");
  in.check_keys(*damping, "damping", {"C", "rayleigh", "modal_ratios"});
  const int given =
      (in.find(*damping, "C") ? 1 : 0) + (in.find(*damping, "rayleigh") ? 1 : 0) + (in.find(*damping, "modal_ratios") ? 1 : 0);
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

void read_forcing(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
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
      if (in.find(f, "dof") || in.find(f, "cos") || in.find(f, "sin"))
        in.fail(shape, field + ".shape", "cannot be combined with dof, cos or sin");
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

void read_parameters(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  if (const toml::value* p = in.find(root, "parameters")) {
    in.table(*p, "parameters");
    // Sorted for a stable order in outputs.
    std::map<std::string, const toml::value*> sorted;
    for (const auto& [key, value] : p->as_table()) sorted[key] = &value;
    for (const auto& [key, value] : sorted) {
      if (const std::string problem = column_name_problem("parameter name", key); !problem.empty()) in.fail(value, "parameters", problem);
      c.parameters.set(key, in.number(*value, "parameters." + key));
    }
  }
  if (c.parameters.find("amplitude") < 0) c.parameters.set("amplitude", 1.0);
}

// adaptive = { min = 3, max = 15, add_above = 1e-4, drop_below = 1e-6 }: min and max required.
void read_adaptive_harmonics(const CaseReader& in, const toml::value& a, AdaptiveHarmonics& out) {
  const std::string field = "harmonic_balance.adaptive";
  in.table(a, field);
  in.check_keys(a, field, {"min", "max", "add_above", "drop_below"});
  out.min = in.integer(in.require(a, "min", field + ".min"), field + ".min");
  out.max = in.integer(in.require(a, "max", field + ".max"), field + ".max");
  out.add_above = in.number_or(a, "add_above", field + ".add_above", out.add_above);
  out.drop_below = in.number_or(a, "drop_below", field + ".drop_below", out.drop_below);
  try {
    out.validate();
  } catch (const std::invalid_argument& e) {
    in.fail(&a, "", e.what());
  }
}

}  // namespace

void read_settings(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  if (const toml::value* h = in.find(root, "harmonic_balance")) {
    in.table(*h, "harmonic_balance");
    in.check_keys(*h, "harmonic_balance", {"harmonics", "samples", "condensation", "subharmonic", "adaptive"});
    const toml::value* list = in.find(*h, "harmonics");
    if (list && list->is_array()) {
      // A list of harmonics: sorted, unique integers >= 0 (0 only if listed); H is its largest.
      std::vector<int> harmonics;
      for (size_t i = 0; i < list->as_array().size(); ++i)
        harmonics.push_back(in.integer(list->as_array()[i], "harmonic_balance.harmonics[" + std::to_string(i) + "]"));
      if (harmonics.empty())
        in.fail(list, "harmonic_balance.harmonics", "an empty list (give H, or the harmonics to balance, e.g. [1, 3, 5])");
      c.harmonic_balance.harmonic_list = harmonics;
      c.harmonic_balance.harmonics = harmonics.back();
      try {
        c.harmonic_balance.validate();
      } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        if (what.rfind("harmonic_balance.harmonics:", 0) == 0) in.fail(list, "harmonic_balance.harmonics", what.substr(what.find(':') + 2));
      }
      c.harmonic_balance.select(harmonics);
    } else {
      c.harmonic_balance.harmonics = in.integer_or(*h, "harmonics", "harmonic_balance.harmonics", c.harmonic_balance.harmonics);
    }
    c.harmonic_balance.subharmonic = in.integer_or(*h, "subharmonic", "harmonic_balance.subharmonic", 1);
    c.harmonic_balance.samples = in.integer_or(*h, "samples", "harmonic_balance.samples", 0);
    c.harmonic_balance.condensation = in.choice_or(*h, "condensation", Condensation::automatic);
    if (const toml::value* a = in.find(*h, "adaptive")) read_adaptive_harmonics(in, *a, c.harmonic_balance.adaptive);
    try {
      c.harmonic_balance.validate();
    } catch (const std::invalid_argument& e) {
      in.fail(h, "", e.what());
    }
  }
  const toml::value& cont = in.table(in.require(root, "continuation", "continuation"), "continuation");
  in.check_keys(cont, "continuation",
                {"omega_start", "omega_end", "length_scale", "step", "step_min", "step_max", "max_points", "max_iterations",
                 "target_iterations", "tolerance", "max_angle", "target_angle", "predictor", "corrector", "wall_time_limit", "locate",
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
  co.target_angle = in.number_or(cont, "target_angle", "continuation.target_angle", std::min(co.target_angle, co.max_angle));
  co.predictor = in.choice_or(cont, "predictor", co.predictor);
  co.corrector = in.choice_or(cont, "corrector", co.corrector);
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
    in.check_keys(*st, "stability", {"method", "monodromy_steps", "hill_solver", "cross_check", "every_point"});
    if (const toml::value* every = in.find(*st, "every_point")) {
      if (!every->is_boolean()) in.fail(every, "stability.every_point", "expected true or false");
      o.stability.every_point = every->as_boolean();
    }
    o.stability.cross_check = in.choice_or(*st, "cross_check", o.stability.cross_check);
    o.stability.hill_solver = in.choice_or(*st, "hill_solver", o.stability.hill_solver);
    o.stability.method = in.choice_or(*st, "method", o.stability.method);
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

// DLFT contact forces are Lagrange multipliers of the harmonic balance: no time-domain law, so no
// Floquet analysis of them.
void check_stability_supported(const CaseReader& in, const toml::value& root, const CaseDefinition& c) {
  if (c.nfrc.stability.method == StabilityMethod::none) return;
  for (size_t i = 0; i < c.elements.size(); ++i) {
    if (!c.elements[i]->uses_linear_residual()) continue;
    const toml::value& e = root.at("elements").as_array()[i];
    in.fail(in.find(e, "law"), "elements[" + std::to_string(i) + "].law",
            "\"dlft\" has no stability analysis (its forces are Lagrange multipliers of the harmonic balance): set stability.method = "
            "\"none\"");
  }
}

// A forcing harmonic above the truncation would silently vanish from the balance.
void check_forcing_within_harmonics(const CaseReader& in, const toml::value& root, const CaseDefinition& c) {
  const toml::value* forcing = in.find(root, "forcing");
  const int harmonics = c.harmonic_balance.harmonics;
  for (size_t i = 0; forcing && i < forcing->as_array().size(); ++i) {
    const toml::value& f = forcing->as_array()[i];
    const std::string field = "forcing[" + std::to_string(i) + "].harmonic";
    const int order = in.integer_or(f, "harmonic", field, 1);
    const toml::value* where = in.find(f, "harmonic") ? in.find(f, "harmonic") : &f;
    if (order * c.harmonic_balance.subharmonic > harmonics)
      in.fail(where, field,
              "must be <= harmonic_balance.harmonics = " + std::to_string(harmonics) + " (a higher harmonic is not represented)");
    const std::vector<int> listed = c.harmonic_balance.selected_harmonics();
    const int basis_order = order * c.harmonic_balance.subharmonic;
    if (std::find(listed.begin(), listed.end(), basis_order) == listed.end())
      in.fail(where, field, "harmonic " + std::to_string(order) + " is not in the list harmonic_balance.harmonics (it would be dropped)");
  }
}

namespace {

// An output's description labels an axis: longer text would not fit beside it.
constexpr size_t kLongestDescription = 80;

void read_outputs(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* outputs = in.find(root, "outputs");
  if (!outputs) return;
  if (!outputs->is_array()) in.fail(outputs, "outputs", "expected an array of tables ([[outputs]])");
  std::set<std::string> names;
  for (size_t i = 0; i < outputs->as_array().size(); ++i) {
    const std::string field = "outputs[" + std::to_string(i) + "]";
    const toml::value& o = in.table(outputs->as_array()[i], field);
    in.check_keys(o, field, {"name", "dof", "description"});
    OutputDof out;
    out.dof = dof_index(in, c.model, in.require(o, "dof", field + ".dof"), field + ".dof");
    out.name = in.string_or(o, "name", field + ".name", c.model.dof_names[static_cast<size_t>(out.dof)]);
    if (out.name.empty() || out.name.find_first_of(",\"\n ") != std::string::npos)
      in.fail(&o, field + ".name", "must be non-empty without commas, quotes or spaces (it names CSV columns)");
    if (!names.insert(out.name).second) in.fail(&o, field + ".name", "output name '" + out.name + "' appears twice");
    out.description = in.string_or(o, "description", field + ".description", "");
    if (out.description.size() > kLongestDescription || out.description.find_first_of("\n\r") != std::string::npos)
      in.fail(&o, field + ".description",
              "at most " + std::to_string(kLongestDescription) + " characters on one line (it labels figure axes)");
    c.outputs.push_back(out);
  }
}

}  // namespace

// Applies "NAME=VALUE" overrides to the parsed TOML document.
void apply_overrides(const CaseReader& in, toml::value& root, const std::vector<std::string>& overrides) {
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
        throw CaseError("--set " + name + ": '" + text + "' is one value followed by a '#' comment (quote a string: " + name +
                        "='\"...\"')");
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
        throw CaseError("--set " + name + ": unknown parameter" +
                        (guess.empty() ? " (known: " + join(known) + ")" : " (did you mean '" + guess + "'?)"));
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
        if (close != key.size() - 1 || close == open + 1 || key.find_first_not_of("0123456789", open + 1) != close)
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

CaseDefinition load_case(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_bounded_file(path, kMaxCaseFileBytes, "a TOML case file");
  // TOML is UTF-8. Checked here because toml11 3.7 reads out of bounds when it reports invalid
  // UTF-8 inside a string (fuzzing: a literal string holding the byte 0xE0).
  if (const std::size_t bad = first_invalid_utf8(text); bad != std::string_view::npos) {
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n');
    throw CaseError(path + ":" + std::to_string(line) + ": not valid UTF-8 (byte " + std::to_string(bad) +
                    "); a TOML case file must be UTF-8");
  }
  check_toml_nesting(text, path);
  // toml11 is quadratic in a line's length: long lines are broken first (toml_long_lines.hpp).
  TomlLines parsed = break_long_toml_lines(text);
  toml::value root;
  try {
    std::istringstream stream(std::move(parsed.text));
    root = toml::parse(stream, path);
  } catch (const toml::syntax_error& e) {
    // toml11 reports over several lines; keep the first line and the line number.
    std::string msg = e.what();
    const std::string first = msg.substr(0, msg.find('\n'));
    const std::string line = std::to_string(parsed.lines.original(static_cast<long>(e.location().line())));
    throw CaseError(path + ":" + line +
                    ": TOML syntax error: " + first.substr(first.find(':') == std::string::npos ? 0 : first.find(':') + 2));
  } catch (const std::exception& e) {
    std::string msg = e.what();
    throw CaseError(path + ": cannot read: " + msg.substr(0, msg.find('\n')));
  }
  CaseReader in(path, std::move(parsed.lines));
  if (!root.is_table()) throw CaseError(path + ": expected a TOML table at the top level");
  // Before the overrides, so that `--set elements[i]...` addresses element i of the expanded list.
  expand_element_templates(in, root);
  apply_overrides(in, root, overrides);
  in.check_keys(root, "",
                {"model", "rotation", "damping", "forcing", "forcing_growth", "base_motion", "parameters", "elements", "harmonic_balance",
                 "continuation", "stability", "outputs", "study"});
  CaseDefinition c;
  c.path = path;
  read_model(in, root, c);
  read_rotation(in, root, c);  // before the damping: modal ratios are those of the modes at speed
  read_damping(in, root, c);
  add_gyroscopic_damping(c);
  read_forcing(in, root, c);
  read_forcing_growth(in, root, c);
  read_base_motion(in, root, c);
  try {
    c.model.validate();
  } catch (const std::invalid_argument& e) {
    throw CaseError(path + ": " + e.what());
  }
  read_parameters(in, root, c);
  fix_rotation_parameter(c);
  read_elements(in, root, c);
  read_settings(in, root, c);
  check_stability_supported(in, root, c);
  check_forcing_within_harmonics(in, root, c);
  check_base_motion_within_harmonics(in, root, c);
  read_outputs(in, root, c);
  read_study(in, root, c);
  return c;
}

int parameter_index(const ParameterSet& parameters, const std::string& name, const std::string& field) {
  const int index = parameters.find(name);
  if (index >= 0) {
    if (const std::string why = parameters.fixed_reason(index); !why.empty()) throw CaseError(field + ": '" + name + "' " + why);
    return index;
  }
  std::string known;
  for (const std::string& n : parameters.names()) known += (known.empty() ? "" : ", ") + n;
  throw CaseError(field + ": unknown parameter '" + name + "' (the case has: " + known + ")");
}

}  // namespace hbtrack
