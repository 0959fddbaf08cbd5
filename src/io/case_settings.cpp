// with_overrides: `--set NAME=VALUE` on a case already read (the Python runs' keyword options).
// The case's settings are written into a TOML document as the case file holds them, the
// overrides applied by the case file's own code and the sections read back by its readers, so
// the keys, defaults and error messages are those of `--set` on the file.
#include <toml.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "case_reader.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack {

namespace {

// The sections a computation may change; the model, elements, forcing and outputs are the case's.
const std::vector<std::string> kSettingSections{"parameters", "harmonic_balance", "continuation", "stability"};

// The first component of an override's name ("continuation" of "continuation.step", "elements"
// of "elements[0].law"); "" for a named parameter.
std::string section_of(const std::string& override_text) {
  const std::string name = override_text.substr(0, override_text.find('='));
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return "";
  return name.substr(0, std::min(dot, name.find('[')));
}

toml::value settings_document(const CaseDefinition& c) {
  toml::table parameters;
  for (int i = 0; i < c.parameters.size(); ++i) parameters[c.parameters.names()[static_cast<size_t>(i)]] = c.parameters.value(i);
  const HarmonicBalanceOptions& h = c.harmonic_balance;
  toml::value harmonics = h.harmonics;
  if (!h.harmonic_list.empty()) harmonics = toml::array(h.harmonic_list.begin(), h.harmonic_list.end());
  const NfrcOptions& n = c.nfrc;
  const ContinuationOptions& co = n.continuation;
  const StabilityOptions& st = n.stability;
  toml::array forcing, elements(c.elements.size(), toml::table{});
  toml::table harmonic_balance{
      {"harmonics", harmonics}, {"subharmonic", h.subharmonic}, {"samples", h.samples}, {"condensation", to_string(h.condensation)}};
  if (h.adaptive.enabled())
    harmonic_balance["adaptive"] = toml::table{
        {"min", h.adaptive.min}, {"max", h.adaptive.max}, {"add_above", h.adaptive.add_above}, {"drop_below", h.adaptive.drop_below}};
  for (const auto& f : c.model.forcing) forcing.push_back(toml::table{{"harmonic", f.order}});
  toml::value root = toml::table{{"parameters", parameters},
                                 {"harmonic_balance", harmonic_balance},
                                 {"continuation", toml::table{{"omega_start", n.omega_start},
                                                              {"omega_end", n.omega_end},
                                                              {"length_scale", n.length_scale},
                                                              {"step", co.step},
                                                              {"step_min", co.step_min},
                                                              {"step_max", co.step_max},
                                                              {"max_points", co.max_points},
                                                              {"max_iterations", co.max_iterations},
                                                              {"target_iterations", co.target_iterations},
                                                              {"tolerance", co.tolerance},
                                                              {"max_angle", co.max_angle},
                                                              {"target_angle", co.target_angle},
                                                              {"predictor", to_string(co.predictor)},
                                                              {"corrector", to_string(co.corrector)},
                                                              {"wall_time_limit", co.wall_time_limit},
                                                              {"locate", co.locate},
                                                              {"reuse_factorization", co.reuse_factorization},
                                                              {"contraction", co.contraction}}},
                                 {"stability", toml::table{{"method", to_string(st.method)},
                                                           {"monodromy_steps", st.monodromy_steps},
                                                           {"hill_solver", to_string(st.hill_solver)},
                                                           {"cross_check", to_string(st.cross_check)},
                                                           {"every_point", st.every_point}}},
                                 // Only what the checks of the settings against the model read: each forcing's harmonic,
                                 // and one (empty) entry per element.
                                 {"forcing", forcing},
                                 {"elements", elements}};
  // The reader derives the step bounds from the step when the file leaves them out: left out
  // here when they are still that, so that an override of the step moves them as `--set` does.
  const ContinuationOptions defaults;
  toml::table& continuation = root.at("continuation").as_table();
  if (co.step_min == std::min(defaults.step_min, co.step)) continuation.erase("step_min");
  if (co.step_max == std::max(defaults.step_max, co.step)) continuation.erase("step_max");
  if (co.target_angle == std::min(defaults.target_angle, co.max_angle)) continuation.erase("target_angle");
  return root;
}

}  // namespace

CaseDefinition with_overrides(const CaseDefinition& c, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const std::string section = section_of(o);
    if (!section.empty() && std::find(kSettingSections.begin(), kSettingSections.end(), section) == kSettingSections.end())
      throw CaseError("--set " + o.substr(0, o.find('=')) + ": only named parameters and the " + join(kSettingSections) +
                      " keys change on a computation; '" + section + "' is the case's (change it with load_case(path, set=...))");
  }
  for (const std::string& o : overrides) {
    const std::string name = o.substr(0, o.find('='));
    const int index = c.parameters.find(name);
    if (index >= 0 && !c.parameters.fixed_reason(index).empty())
      throw CaseError("--set " + name + ": '" + name + "' " + c.parameters.fixed_reason(index) + " (load_case(path, set=...) rebuilds it)");
  }
  CaseReader in(c.path);
  toml::value root = settings_document(c);
  apply_overrides(in, root, overrides);
  for (const std::string& section : kSettingSections) in.table(root.at(section), section);
  CaseDefinition out = c;
  // Values only: the elements hold the parameters' indices.
  for (const auto& [name, value] : root.at("parameters").as_table()) out.parameters.set(name, in.number(value, "parameters." + name));
  out.harmonic_balance = HarmonicBalanceOptions{};
  out.nfrc = NfrcOptions{};
  read_settings(in, root, out);
  check_stability_supported(in, root, out);
  check_forcing_within_harmonics(in, root, out);
  return out;
}

}  // namespace hbtrack
