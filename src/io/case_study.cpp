#include "case_study.hpp"

#include <array>
#include <string>
#include <utility>

namespace hbtrack {

namespace {

using Eigen::VectorXd;

// `hbtrack torus`'s own limits (runs/torus.cpp): a dense 2-D basis, H2 = 4 by default.
constexpr int kMaxTorusHarmonics = 64, kDefaultTorusH2 = 4;

// study.backbone (a table {mode, range} or an array of them) and study.switch (a boolean).
void read_study_branches(const CaseReader& in, const toml::value& st, CaseDefinition& c) {
  if (const toml::value* sw = in.find(st, "switch")) {
    if (!sw->is_boolean()) in.fail(sw, "study.switch", "expected true or false (switch at every BP and PD of the nominal NFRC)");
    c.study.switch_branches = sw->as_boolean();
  }
  const toml::value* bb = in.find(st, "backbone");
  if (!bb) return;
  const bool several = bb->is_array();
  const size_t count = several ? bb->as_array().size() : 1;
  for (size_t i = 0; i < count; ++i) {
    const toml::value& b = several ? bb->as_array()[i] : *bb;
    const std::string field = several ? "study.backbone[" + std::to_string(i) + "]" : "study.backbone";
    if (!b.is_table()) in.fail(&b, field, "expected a table {mode = K, range = [lo, hi]} (or an array of them)");
    in.check_keys(b, field, {"mode", "range"});
    StudyBackbone s;
    const toml::value& mode = in.require(b, "mode", field + ".mode");
    s.mode = in.integer(mode, field + ".mode");
    if (s.mode < 1 || s.mode > c.model.dofs())
      in.fail(&mode, field + ".mode",
              "must be a linear mode of the model, from 1 to " + std::to_string(c.model.dofs()) + ", got " + std::to_string(s.mode));
    const toml::value& range = in.require(b, "range", field + ".range");
    const VectorXd r = in.vector(range, field + ".range");
    if (r.size() != 2 || !(0 < r(0) && r(0) < r(1)))
      in.fail(&range, field + ".range", "expected [lo, hi] modal amplitudes with 0 < lo < hi");
    s.min = r(0);
    s.max = r(1);
    for (const StudyBackbone& other : c.study.backbones)
      if (other.mode == s.mode) in.fail(&mode, field + ".mode", "mode " + std::to_string(s.mode) + " appears twice");
    c.study.backbones.push_back(s);
  }
}

// study.torus: true, or a table {harmonics = [H1, H2], samples = [N1, N2]} (each optional) of
// `hbtrack torus`'s --harmonics and --samples; checked here so that a bad value fails the study
// before it starts, not as a refused step after its NFRC.
void read_study_torus(const CaseReader& in, const toml::value& st, CaseDefinition& c) {
  const toml::value* t = in.find(st, "torus");
  if (!t) return;
  StudyTorus& torus = c.study.torus;
  if (t->is_boolean()) {
    torus.enabled = t->as_boolean();
    return;
  }
  if (!t->is_table())
    in.fail(t, "study.torus", "expected true or false, or a table {harmonics = [H1, H2], samples = [N1, N2]} (each optional)");
  in.check_keys(*t, "study.torus", {"harmonics", "samples"});
  torus.enabled = true;
  auto integer_pair = [&](const char* key) -> std::pair<const toml::value*, std::array<int, 2>> {
    const std::string field = std::string("study.torus.") + key;
    const toml::value* v = in.find(*t, key);
    if (!v) return {nullptr, {0, 0}};
    if (!v->is_array() || v->as_array().size() != 2) in.fail(v, field, "expected two integers [A, B]");
    return {v, {in.integer(v->as_array()[0], field + "[0]"), in.integer(v->as_array()[1], field + "[1]")}};
  };
  const auto [harmonics, h] = integer_pair("harmonics");
  if (harmonics && !(1 <= h[0] && h[0] <= kMaxTorusHarmonics && 1 <= h[1] && h[1] <= kMaxTorusHarmonics))
    in.fail(harmonics, "study.torus.harmonics",
            "must be [H1, H2] with 1 <= H1, H2 <= " + std::to_string(kMaxTorusHarmonics) + " (the forcing's and the NS phase's)");
  const auto [samples, n] = integer_pair("samples");
  // Without harmonics the torus takes the case's H and 4 (`hbtrack torus`'s defaults).
  const int h1 = harmonics ? h[0] : c.harmonic_balance.harmonics, h2 = harmonics ? h[1] : kDefaultTorusH2;
  if (samples && !(n[0] >= 2 * h1 + 1 && n[1] >= 2 * h2 + 1))
    in.fail(samples, "study.torus.samples",
            "must be [N1, N2] with N1 >= 2 H1 + 1 = " + std::to_string(2 * h1 + 1) + " and N2 >= 2 H2 + 1 = " + std::to_string(2 * h2 + 1));
  if (harmonics) torus.h1 = h[0], torus.h2 = h[1];
  if (samples) torus.n1 = n[0], torus.n2 = n[1];
}

}  // namespace

void read_study(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* st = in.find(root, "study");
  if (!st) return;
  in.table(*st, "study");
  in.check_keys(*st, "study",
                {"track", "backbone", "switch", "max_points", "simulate_periods", "simulate_element_steps", "max_added_curves",
                 "track_ns_pd", "torus", "convergence"});
  StudySettings& study = c.study;
  study.max_points = in.integer_or(*st, "max_points", "study.max_points", study.max_points);
  if (study.max_points < 2) in.fail(&st->at("max_points"), "study.max_points", "must be >= 2");
  study.simulate_periods = in.integer_or(*st, "simulate_periods", "study.simulate_periods", study.simulate_periods);
  if (study.simulate_periods < 0) in.fail(&st->at("simulate_periods"), "study.simulate_periods", "must be >= 0");
  study.simulate_element_steps = in.integer_or(*st, "simulate_element_steps", "study.simulate_element_steps", study.simulate_element_steps);
  if (study.simulate_element_steps < 0)
    in.fail(&st->at("simulate_element_steps"), "study.simulate_element_steps", "must be >= 0 (0: the steps per period)");
  study.max_added_curves = in.integer_or(*st, "max_added_curves", "study.max_added_curves", study.max_added_curves);
  if (study.max_added_curves < 0 || study.max_added_curves > 100)
    in.fail(&st->at("max_added_curves"), "study.max_added_curves", "must be in [0, 100]");
  if (const toml::value* ns = in.find(*st, "track_ns_pd")) {
    if (!ns->is_boolean()) in.fail(ns, "study.track_ns_pd", "expected true or false (follow every NS and PD point of the nominal NFRC)");
    study.track_ns_pd = ns->as_boolean();
  }
  if (const toml::value* conv = in.find(*st, "convergence")) {
    in.table(*conv, "study.convergence");
    in.check_keys(*conv, "study.convergence", {"harmonics", "samples"});
    study.convergence_harmonics = in.integer_or(*conv, "harmonics", "study.convergence.harmonics", 0);
    study.convergence_samples = in.integer_or(*conv, "samples", "study.convergence.samples", 0);
    // harmonics = 0 turns the check off (e.g. with --set study.convergence.harmonics=0).
    if (study.convergence_harmonics < 0 ||
        (study.convergence_harmonics > 0 && study.convergence_samples < 2 * study.convergence_harmonics + 1))
      in.fail(conv, "study.convergence", "expected {harmonics = H >= 1, samples = N >= 2 H + 1} (H = 0: no check)");
  }
  read_study_branches(in, *st, c);
  read_study_torus(in, *st, c);
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
      in.fail(&name, field + ".parameter",
              "unknown parameter '" + s.parameter + "'" +
                  (guess.empty() ? " (declare it in [parameters])" : " (did you mean '" + guess + "'?)"));
    }
    const toml::value& range = in.require(t, "range", field + ".range");
    const VectorXd r = in.vector(range, field + ".range");
    if (r.size() != 2 || !(r(0) < r(1))) in.fail(&range, field + ".range", "expected [lo, hi] with lo < hi");
    s.min = r(0);
    s.max = r(1);
    const double value = c.parameters.value(c.parameters.find(s.parameter));
    if (!(s.min <= value && value <= s.max))
      in.fail(&range, field + ".range",
              "must contain the case's " + s.parameter + " = " + std::to_string(value) + " (tracking starts there)");
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

}  // namespace hbtrack
