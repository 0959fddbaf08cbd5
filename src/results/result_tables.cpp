#include "hbtrack/results/result_tables.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>

#include "hbtrack/results/model_fingerprint.hpp"

namespace hbtrack {

using nlohmann::json;

json options_json(const CaseDefinition& c, const HarmonicBalance& hbm) {
  json harmonic_balance = {{"harmonics", c.harmonic_balance.harmonics},
                           {"samples", hbm.basis().samples()},
                           {"condensation", hbm.condensation_method()},
                           {"unknowns", hbm.unknowns()}};
  // The dofs whose harmonics are the unknowns (states.csv has every dof's: a reader picks these).
  json retained = json::array();
  for (int dof : hbm.retained()) retained.push_back(hbm.model().dof_names[static_cast<size_t>(dof)]);
  harmonic_balance["retained_dofs"] = retained;
  // A selection or a subharmonic basis: the list as given, and nu (states.csv holds, per listed
  // harmonic k, a_k then b_k over the retained dofs; k is a multiple of omega / nu).
  if (!c.harmonic_balance.harmonic_list.empty()) harmonic_balance["harmonics"] = c.harmonic_balance.harmonic_list;
  if (c.harmonic_balance.subharmonic != 1) harmonic_balance["subharmonic"] = c.harmonic_balance.subharmonic;
  // H changes along the branch (harmonics: the H it started from; states.csv is padded to max).
  if (const AdaptiveHarmonics& a = c.harmonic_balance.adaptive; a.enabled())
    harmonic_balance["adaptive"] = {{"min", a.min}, {"max", a.max}, {"add_above", a.add_above}, {"drop_below", a.drop_below}};
  json params = json::object();
  for (int i = 0; i < hbm.parameters().size(); ++i) params[hbm.parameters().names()[static_cast<size_t>(i)]] = hbm.parameters().value(i);
  const auto& co = c.nfrc.continuation;
  return {{"case", c.path},
          {"model_fnv1a", model_fingerprint(c.model, c.elements)},  // refuses a --resume on an edited model
          {"parameters", params},
          {"harmonic_balance", harmonic_balance},
          {"continuation",
           {{"omega_start", c.nfrc.omega_start},
            {"omega_end", c.nfrc.omega_end},
            {"length_scale", c.nfrc.length_scale},
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
          {"stability",
           {{"method", to_string(c.nfrc.stability.method)},
            {"monodromy_steps", c.nfrc.stability.monodromy_steps},
            {"hill_solver", to_string(c.nfrc.stability.hill_solver)},
            {"cross_check", to_string(c.nfrc.stability.cross_check)},
            {"every_point", c.nfrc.stability.every_point}}}};
}

json outputs_json(const CaseDefinition& c) {
  json outputs = json::array();
  for (const auto& out : c.outputs) {
    json entry = {{"name", out.name}, {"dof", c.model.dof_names[static_cast<size_t>(out.dof)]}};
    if (!out.description.empty()) entry["description"] = out.description;
    outputs.push_back(entry);
  }
  return outputs;
}

void add_outputs(json& j, const CaseDefinition& c, const RecordedPoint& p) {
  for (size_t i = 0; i < c.outputs.size() && i < p.outputs.size(); ++i) {
    j["max_" + c.outputs[i].name] = p.outputs[i].max;
    j["min_" + c.outputs[i].name] = p.outputs[i].min;
    j["h1_" + c.outputs[i].name] = p.outputs[i].h1;
  }
}

namespace {
std::string column_name(const std::string& prefix, const std::string& k, const std::string& output) {
  std::string column = prefix;  // appended, not operator+: GCC 12's false -Wrestrict at -O3
  column += k;
  column += "_";
  column += output;
  return column;
}

// The first columns (max_, min_, h1_ per output) are the historical ones that other tools read by
// position; the other harmonics' magnitudes and all phases come after them.
void add_output_columns(std::vector<std::string>& header, const CaseDefinition& c) {
  for (const auto& o : c.outputs)
    for (const char* kind : {"max", "min", "h1"}) header.push_back(column_name(kind, "", o.name));
  // The harmonics balanced, named by their multiple of omega (k / nu: "3", "0.5"); h1 is above.
  // An adaptive run's rows hold 0..adaptive.max, zeros above each point's own H.
  std::vector<int> listed = c.harmonic_balance.selected_harmonics();
  if (c.harmonic_balance.adaptive.enabled()) {
    listed.clear();
    for (int k = 0; k <= c.harmonic_balance.adaptive.max; ++k) listed.push_back(k);
  }
  const int nu = c.harmonic_balance.subharmonic;
  for (const auto& o : c.outputs) {
    for (int k : listed)
      if (k != nu) header.push_back(column_name("h", harmonic_label(k, nu), o.name));
    for (int k : listed)
      if (k > 0) header.push_back(column_name("phase", harmonic_label(k, nu), o.name));
  }
}

void add_output_values(std::vector<double>& row, const RecordedPoint& p) {
  for (const auto& v : p.outputs) row.insert(row.end(), {v.max, v.min, v.h1});
  for (const auto& v : p.outputs) {
    if (v.harmonics.size() == 0) continue;  // not recorded: the row comes out short, CsvAppender refuses it
    for (int k : p.harmonic_numbers)
      if (k != p.subharmonic) row.push_back(harmonic_magnitude(v.harmonics, k));
    for (int k : p.harmonic_numbers)
      if (k > 0) row.push_back(harmonic_phase(v.harmonics, k));
  }
}
}  // namespace

std::vector<std::string> branch_header(const CaseDefinition& c) {
  std::vector<std::string> h{"omega"};
  if (c.nfrc.stability.enabled()) h.push_back("stable");
  add_output_columns(h, c);
  // Last, so that the columns other tools read by position stay where they were.
  if (c.harmonic_balance.adaptive.enabled()) h.push_back("harmonics");
  return h;
}

std::vector<double> branch_row(const RecordedPoint& p) {
  std::vector<double> row{p.omega};
  if (p.stable >= 0) row.push_back(p.stable);
  add_output_values(row, p);
  if (p.balanced_harmonics > 0) row.push_back(p.balanced_harmonics);
  return row;
}

namespace {
// The methods that decide a point's stability: the keys of summary.json's stability_methods, and
// in this order the codes of stability.csv's `method` column (its cells are numbers).
// "bracketed" points have no exponents of their own, hence no stability.csv rows.
constexpr std::array<const char*, 4> kStabilityMethods{"hill", "monodromy", "shooting", kBracketedStability};

double stability_method_code(const std::string& method) {
  for (size_t i = 0; i < kStabilityMethods.size(); ++i)
    if (method == kStabilityMethods[i]) return static_cast<double>(i);
  return -1;  // not computed
}

json method_counts() {
  json counts = json::object();
  for (const char* method : kStabilityMethods) counts[method] = 0;
  return counts;
}
}  // namespace

std::vector<std::string> stability_header() {
  return {"point", "omega", "k", "exponent_real", "exponent_imag", "multiplier_real", "multiplier_imag", "method"};
}

std::vector<std::vector<double>> stability_rows(int point, const RecordedPoint& p) {
  std::vector<Eigen::Index> order(static_cast<size_t>(p.floquet_exponents.size()));
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Eigen::Index>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return p.floquet_exponents(a).real() > p.floquet_exponents(b).real(); });
  std::vector<std::vector<double>> rows;
  for (size_t k = 0; k < order.size(); ++k) {
    const std::complex<double> exponent = p.floquet_exponents(order[k]), multiplier = p.floquet_multipliers(order[k]);
    rows.push_back({static_cast<double>(point), p.omega, static_cast<double>(k), exponent.real(), exponent.imag(), multiplier.real(),
                    multiplier.imag(), stability_method_code(p.stability_method)});
  }
  return rows;
}

std::vector<std::string> state_header(int unknowns) {
  std::vector<std::string> h{"omega"};
  for (int i = 0; i < unknowns; ++i) {
    std::string column = "x";  // appended, not operator+: GCC 12's false -Wstringop-overflow at -O3
    column += std::to_string(i);
    h.push_back(column);
  }
  return h;
}

std::vector<double> state_row(double omega, const Eigen::VectorXd& x) {
  std::vector<double> row{omega};
  row.insert(row.end(), x.data(), x.data() + x.size());
  return row;
}

void add_continuation_counts(json& summary, const ContinuationSummary& s) {
  summary["stop_reason"] = to_string(s.stop_reason);
  summary["points"] = s.points;
  summary["newton_iterations"] = s.newton_iterations;
  summary["failed_steps"] = s.failed_steps;
  summary["step_halvings"] = s.step_halvings;
  summary["jacobian_evaluations"] = s.jacobian_evaluations;
  summary["chord_iterations"] = s.chord_iterations;
  summary["residual_evaluations"] = s.residual_evaluations;
  summary["factorizations"] = s.factorizations;
  summary["corners_stepped_over"] = s.corners_stepped_over;
}

void add_nfrc_summary(json& summary, const CaseDefinition& c, HarmonicBalance& hbm, const NfrcResult& r) {
  const auto& s = r.continuation.summary;
  add_continuation_counts(summary, s);
  summary["options"]["continuation"]["length_scale"] = r.length_scale;
  summary["outputs"] = outputs_json(c);
  json special = json::array();
  for (const auto& sp : r.continuation.special_points) {
    json j = {{"type", to_string(sp.type)}, {"index", sp.index}, {"omega", sp.lambda}, {"located", sp.located}};
    if (!sp.decided_by.empty()) j["stability_method"] = sp.decided_by;
    j["parameters"] = summary["options"]["parameters"];
    // Outputs of the special point itself (a located one lies between two rows of branch.csv).
    add_outputs(j, c, record_point(hbm, sp.u, sp.lambda, c.outputs));
    special.push_back(j);
  }
  summary["special_points"] = special;
  // What decided the stability of the rows and of the PD/NS points (Hill, or the monodromy
  // matrix where Hill is unreliable: see stability.cross_check).
  if (c.nfrc.stability.enabled()) {
    json decided = method_counts();
    for (const RecordedPoint& p : r.recorded)
      if (!p.stability_method.empty()) decided[p.stability_method] = decided[p.stability_method].get<int>() + 1;
    json special_decided = method_counts();
    for (const auto& sp : r.continuation.special_points)
      if (!sp.decided_by.empty()) special_decided[sp.decided_by] = special_decided[sp.decided_by].get<int>() + 1;
    summary["stability_methods"] = {{"points", decided}, {"special_points", special_decided}};
  }
}

void add_adaptive_harmonics_summary(json& summary, const NfrcResult& r, int retained_dofs) {
  if (r.recorded.empty()) return;
  int lowest = r.recorded.front().balanced_harmonics, highest = lowest, changes = 0;
  double sum = 0;
  for (size_t i = 0; i < r.recorded.size(); ++i) {
    const int h = r.recorded[i].balanced_harmonics;
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
    sum += h;
    if (i > 0 && h != r.recorded[i - 1].balanced_harmonics) ++changes;
  }
  const double mean = sum / static_cast<double>(r.recorded.size());
  const auto unknowns = [&](double h) { return retained_dofs * (2 * h + 1); };
  summary["adaptive_harmonics"] = {
      {"harmonics", {{"min", lowest}, {"max", highest}, {"mean", mean}}},
      {"unknowns", {{"min", static_cast<int>(unknowns(lowest))}, {"max", static_cast<int>(unknowns(highest))}, {"mean", unknowns(mean)}}},
      {"changes", changes}};
  json& special = summary["special_points"];
  for (size_t i = 0; i < special.size() && i < r.continuation.special_points.size(); ++i) {
    const size_t row = static_cast<size_t>(r.continuation.special_points[i].index);
    if (row < r.recorded.size()) special[i]["harmonics"] = r.recorded[row].balanced_harmonics;
  }
}

std::vector<std::string> tracking_header(const CaseDefinition& c, const std::string& parameter, TrackedPoint tracked) {
  std::vector<std::string> h{"leg", "omega", parameter};
  if (tracked != TrackedPoint::limit_point) h.push_back("ns_frequency");
  add_output_columns(h, c);
  return h;
}

std::vector<double> tracking_row(const FoldCurvePoint& p, TrackedPoint tracked) {
  std::vector<double> row{static_cast<double>(p.leg), p.omega, p.parameter};
  if (tracked != TrackedPoint::limit_point) row.push_back(p.critical_frequency);
  add_output_values(row, p.recorded);
  return row;
}

void add_tracking_summary(json& summary, const CaseDefinition& c, const FoldTrackingResult& r, const std::string& parameter) {
  json legs = json::array();
  int newton = 0, jacobians = 0, residuals = 0, factorizations = 0, chords = 0;
  for (size_t i = 0; i < r.legs.size(); ++i) {
    const ContinuationSummary& s = r.legs[i];
    legs.push_back({{"leg", i + 1},
                    {"towards", i == 0 ? "min" : "max"},
                    {"stop_reason", to_string(s.stop_reason)},
                    {"points", s.points},
                    {"newton_iterations", s.newton_iterations},
                    {"failed_steps", s.failed_steps},
                    {"jacobian_evaluations", s.jacobian_evaluations},
                    {"chord_iterations", s.chord_iterations},
                    {"residual_evaluations", s.residual_evaluations},
                    {"factorizations", s.factorizations},
                    {"wall_s", s.wall_s}});
    newton += s.newton_iterations;
    jacobians += s.jacobian_evaluations;
    residuals += s.residual_evaluations;
    chords += s.chord_iterations;
    factorizations += s.factorizations;
  }
  json special = json::array();
  for (const FoldExtremum& e : r.extrema) {
    json j = {{"type", to_string(e.type)}, {"index", e.index}, {"omega", e.omega}, {parameter, e.parameter}, {"located", e.located}};
    if (std::isfinite(e.critical_frequency)) j["ns_frequency"] = e.critical_frequency;
    add_outputs(j, c, e.recorded);
    special.push_back(j);
  }
  summary["stop_reason"] = to_string(r.stop_reason());
  summary["closed"] = r.closed;
  summary["legs"] = legs;
  summary["points"] = r.curve_points();
  summary["newton_iterations"] = newton;
  summary["jacobian_evaluations"] = jacobians;
  summary["chord_iterations"] = chords;
  summary["residual_evaluations"] = residuals;
  summary["factorizations"] = factorizations;
  summary["special_points"] = special;
  summary["outputs"] = outputs_json(c);
}

json simulation_options_json(IntegrationMethod method, bool from_hbm, int steps_per_period, const SteadyStateOptions& steady) {
  return {{"method", to_string(method)},
          {"initial_state", from_hbm ? "hbm" : "rest"},
          {"steps_per_period", steps_per_period},
          {"max_periods", steady.max_periods},
          {"record_periods", steady.record_periods},
          {"tolerance", steady.tolerance},
          {"confirmations", steady.confirmations},
          {"harmonics", steady.harmonics}};
}

std::vector<std::string> signals_header(const CaseDefinition& c) {
  std::vector<std::string> header{"time"};
  for (const OutputDof& out : c.outputs) header.push_back(out.name);
  return header;
}

std::vector<std::vector<double>> signals_rows(const SteadyStateResult& r) {
  std::vector<std::vector<double>> rows;
  for (Eigen::Index i = 0; i < r.time.size(); ++i) {
    std::vector<double> row{r.time(i)};
    for (Eigen::Index j = 0; j < r.signals.cols(); ++j) row.push_back(r.signals(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

void add_simulation_summary(json& summary, const CaseDefinition& c, const SteadyStateResult& r) {
  summary["converged"] = r.converged;
  summary["periods"] = r.periods;
  summary["stop_reason"] = to_string(r.stop_reason);
  if (!r.message.empty()) summary["message"] = r.message;
  summary["last_change"] = r.last_change;
  summary["steps"] = r.statistics.steps;
  summary["force_evaluations"] = r.statistics.force_evaluations;
  summary["newton_iterations"] = r.statistics.newton_iterations;
  RecordedPoint last_period;
  for (const PeriodSummary& s : r.outputs) last_period.outputs.push_back({s.max, s.min, s.first_harmonic(), s.harmonics});
  add_outputs(summary, c, last_period);
  for (size_t i = 0; i < c.outputs.size() && i < r.outputs.size(); ++i) {
    const Eigen::VectorXd& h = r.outputs[i].harmonics;
    std::string key = "harmonics_";
    key += c.outputs[i].name;
    summary[key] = std::vector<double>(h.data(), h.data() + h.size());
  }
}

FoldScales tracking_scales(HarmonicBalance& hbm, const NfrcOptions& n, double parameter_span) {
  const double reference = n.length_scale > 0 ? n.length_scale : automatic_length_scale(hbm, n.omega_start, n.omega_end);
  FoldScales s;
  s.length = n.length_scale > 0 ? n.length_scale : 0.01 * reference;
  s.omega = std::abs(n.omega_end - n.omega_start);
  s.force = force_scale(hbm, reference);
  s.parameter = parameter_span;
  return s;
}

}  // namespace hbtrack
