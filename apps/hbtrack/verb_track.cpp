// `hbtrack track`: a limit point of a frc result followed in a second parameter;
// `hbtrack isolas`: the isolated branches a tracking curve reveals at one parameter value.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "artefact_warnings.hpp"
#include "cli_common.hpp"
#include "folder_lock.hpp"
#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/results/continuation_state_file.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "result_folder.hpp"
#include "resume_checkpoint.hpp"
#include "stop_request.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;


struct TrackOptions {
  CommonOptions common;
  std::string from, lp, param, range, method;  // method: bordered unless given (or resumed)
  std::string resume;                          // a stopped track result folder to continue
  double time_limit = 0;                       // seconds, 0 for none
};

// --resume DIR: the stopped run's --from, --lp, --param, --range and --method, where not given
// again (given ones must agree: the checkpoint's settings are compared later).
void take_options_of_stopped_run(TrackOptions& o) {
  const json summary = read_summary(o.resume);
  if (!summary.contains("options") || !summary["options"].contains("tracking") || !summary["options"]["tracking"].is_object())
    throw CaseError("--resume: " + o.resume + "/summary.json: options.tracking missing (is it a track result?)");
  const json& t = summary["options"]["tracking"];
  // Before lp_order, --lp counted in summary.json's order: the same number may name another LP.
  if (!t.contains("lp_order"))
    throw CaseError("--resume: " + o.resume + "/summary.json: options.tracking.lp_order missing: written when --lp counted limit points "
                    "in the NFRC's order, not in increasing omega; run the tracking again");
  try {
    if (o.from.empty()) o.from = t.at("from").get<std::string>();
    if (o.lp.empty()) o.lp = std::to_string(t.at("lp").get<long>());
    if (o.param.empty()) o.param = t.at("parameter").get<std::string>();
    if (o.method.empty()) o.method = t.at("method").get<std::string>();
    if (o.range.empty()) o.range = number_text(t.at("range").at(0).get<double>(), 17) + ":" + number_text(t.at("range").at(1).get<double>(), 17);
  } catch (const json::exception& e) {
    throw CaseError("--resume: " + o.resume + "/summary.json: options.tracking: " + e.what());
  }
}

struct IsolaOptions {
  CommonOptions common;
  std::vector<std::string> from;
  std::string at;
  bool locate_only = false;
};

// The case rebuilt with the settings of the result folder `dir`, then the user's --set.
CaseDefinition case_as_in(const CommonOptions& o, const std::string& dir) {
  const CaseDefinition plain = load_case(o.case_path, o.sets);
  std::vector<std::string> overrides = hbm_overrides(dir, plain);
  overrides.insert(overrides.end(), o.sets.begin(), o.sets.end());  // --set wins
  return load_case(o.case_path, overrides);
}

// The starting limit point: LP `lp` (from 1, in increasing omega as the figures number them) of
// DIR/summary.json and its state.
HbmState starting_fold(const std::string& dir, long lp, const HarmonicBalance& hbm) {
  const json summary = read_summary(dir);
  const std::string path = dir + "/summary.json";
  if (!summary.contains("special_points") || !summary["special_points"].is_array())
    throw CaseError(path + ": special_points missing (is --from a frc result?)");
  const std::vector<size_t> rows = limit_point_rows(summary["special_points"]);
  if (static_cast<size_t>(lp) > rows.size())
    throw CaseError("--lp: " + std::to_string(lp) + " is beyond the " + std::to_string(rows.size()) + " limit points of " + path);
  return read_hbm_state(dir + "/special_states.csv", static_cast<long>(rows[lp - 1]), hbm);
}

// After a failed tracking run: the elements whose law the fold systems cannot differentiate, the
// likely cause ("" when every law is smooth).
std::string smoothness_hint(const HarmonicBalance& hbm) {
  std::string hint;
  for (size_t i = 0; i < hbm.elements().size(); ++i) {
    const std::string limit = hbm.elements()[i]->smoothness_limit();
    if (limit.empty()) continue;
    hint += hint.empty() ? "; " : ", ";
    hint += "elements[" + std::to_string(i) + "] (" + hbm.elements()[i]->type() + "): " + limit;
  }
  if (!hint.empty()) hint += ": limit-point tracking needs a law with a smooth Jacobian (law = \"sqrt\")";
  return hint;
}

int run_track(TrackOptions o) {
  const auto t0 = Clock::now();
  if (!o.resume.empty()) {
    if (!o.common.out_dir.empty() && o.common.out_dir != o.resume) throw CaseError("--resume: continues in its own folder, give no other -o");
    o.common.out_dir = o.resume;
    take_options_of_stopped_run(o);
  }
  if (o.common.out_dir.empty()) throw CaseError("--output is required (or --resume DIR)");
  for (const auto& [flag, value] : {std::pair{"--from", &o.from}, {"--lp", &o.lp}, {"--param", &o.param}, {"--range", &o.range}})
    if (value->empty()) throw CaseError(std::string(flag) + " is required (or --resume DIR)");
  if (o.method.empty()) o.method = "bordered";
  const long lp = parse_integer("--lp", o.lp, 1);
  const size_t colon = o.range.find(':');
  if (colon == std::string::npos) throw CaseError("--range: expected LO:HI, got '" + o.range + "'");
  FoldTrackingOptions tracking;
  tracking.parameter_min = parse_number("--range", o.range.substr(0, colon));
  tracking.parameter_max = parse_number("--range", o.range.substr(colon + 1));
  if (!(tracking.parameter_min < tracking.parameter_max)) throw CaseError("--range: must be LO:HI with LO < HI, got '" + o.range + "'");
  tracking.method = parse_flag_choice<TrackingMethod>("--method", o.method);

  const CaseDefinition c = case_as_in(o.common, o.from);
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), o.param, "--param");
  const double start_value = hbm.parameters().value(parameter);
  if (!(tracking.parameter_min <= start_value && start_value <= tracking.parameter_max))
    throw CaseError("--range: must contain " + o.param + " = " + std::to_string(start_value) + " of the limit point");
  const HbmState start = starting_fold(o.from, lp, hbm);
  if (start.x.size() != hbm.unknowns())
    throw CaseError(o.from + "/special_states.csv: holds " + std::to_string(start.x.size()) + " unknowns, the case has " +
                    std::to_string(hbm.unknowns()) + " (results of another case?)");
  tracking.continuation = c.nfrc.continuation;

  const std::string& dir = o.common.out_dir;
  json summary = {{"verb", "track"}, {"options", options_json(c, hbm)}, {"stop_reason", "running"}};
  summary["options"]["tracking"] = {{"from", o.from}, {"lp", lp}, {"lp_order", "omega"}, {"parameter", o.param}, {"method", o.method},
                                    {"range", {tracking.parameter_min, tracking.parameter_max}}};
  const json settings = branch_settings(summary["options"]);
  std::optional<SavedTracking> resumed;
  if (!o.resume.empty()) resumed = checkpoint_to_resume(dir, {"completed", "closed"}, settings, read_tracking_state);
  ensure_directory(dir);
  lock_result_folder(dir);
  const int rows_kept = resumed ? resumed->state.curve_points : 0;
  std::vector<std::string> state_cols{"leg", "omega", o.param};
  for (const std::string& column : dof_state_columns(hbm)) state_cols.push_back(column);
  CsvAppender branch = open_result_csv(dir + "/branch.csv", tracking_header(c, o.param), resumed.has_value(), rows_kept);
  CsvAppender states = open_result_csv(dir + "/states.csv", state_cols, resumed.has_value(), rows_kept);
  if (resumed) summary["resumed_at_point"] = rows_kept;
  write_json_atomically(dir + "/summary.json", summary);

  const FoldScales scales = tracking_scales(hbm, c.nfrc, tracking.parameter_max - tracking.parameter_min);
  Progress progress(o.common.quiet, o.param, tracking.parameter_min, tracking.parameter_max, start_value);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  FoldTrackingRestart restart;
  if (resumed) restart.resume_from = &resumed->state;
  // Between two steps: what --resume needs to go on from there.
  restart.on_state = [&](const FoldTrackingState& state) { write_tracking_state(dir + "/checkpoint.json", state, settings); };
  FoldTrackingResult r;
  try {
    r = track_fold(
        hbm, parameter, start.x, start.omega, scales, tracking, c.outputs,
        [&](const FoldCurvePoint& p, int index) {
          branch.append(tracking_row(p));
          std::vector<double> row{static_cast<double>(p.leg), p.omega, p.parameter};
          const std::vector<double> dofs = dof_state_values(hbm, p.x, p.omega, parameter, p.parameter);
          row.insert(row.end(), dofs.begin(), dofs.end());
          states.append(row);
          progress.update(index, p.omega, p.parameter, p.leg, p.recorded, c.outputs);
          return !stop.requested();
        },
        restart);
  } catch (const std::runtime_error& e) {
    throw RunFailed{e.what()};
  }
  progress.finish();
  add_tracking_summary(summary, c, r, o.param);
  double omega_low = start.omega, omega_high = start.omega;
  for (const FoldCurvePoint& p : r.points) {
    omega_low = std::min(omega_low, p.omega);
    omega_high = std::max(omega_high, p.omega);
  }
  std::vector<std::string> warnings =
      extremum_pairs_below_resolution(r.extrema, o.param, tracking.parameter_max - tracking.parameter_min, omega_high - omega_low);
  for (const ContinuationSummary& leg : r.legs)
    if (leg.stop_reason == "max_points")
      warnings.push_back("a leg stopped at continuation.max_points after " + std::to_string(leg.points) +
                         " points, before the range's end: the curve is incomplete (rerun with a larger --set continuation.max_points)");
  summary["warnings"] = warnings;
  for (const std::string& w : warnings) std::fprintf(stderr, "track: warning: %s\n", w.c_str());
  const bool ok = r.success();
  const std::string failure = stop.reason(r.failure());
  if (!ok) summary["stop_reason"] = failure;
  summary["start"] = {{"omega", start.omega}, {o.param, start_value}};
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  write_json_atomically(dir + "/summary.json", summary);
  if (!ok)
    throw RunFailed{"tracking stopped: " + failure + " after " + std::to_string(r.curve_points()) + " points (kept in " + dir + ")" +
                    smoothness_hint(hbm)};
  if (!o.common.quiet)
    std::fprintf(stderr, "track: %d points, %zu extrema of %s, %s, %.3f s -> %s\n", r.curve_points(), r.extrema.size(), o.param.c_str(),
                 r.closed ? "closed" : "both ways to the range", summary["timings"]["wall_s"].get<double>(), dir.c_str());
  return 0;
}

// The points of a tracking result folder, as curve points (outputs are not needed).
std::vector<FoldCurvePoint> read_tracking_curve(const std::string& dir, const std::string& parameter, const HarmonicBalance& hbm) {
  const CsvTable t = read_csv_table(dir + "/states.csv");
  const int leg = t.column("leg"), omega = t.column("omega"), gamma = t.column(parameter);
  const int first_x = std::max({leg, omega, gamma}) + 1;  // the dofs' harmonics (or x0, x1, ...) follow the leading columns
  const int unknowns = hbm.unknowns();
  if (is_unknown_layout({t.header.begin() + first_x, t.header.end()}) && static_cast<int>(t.header.size()) - first_x != unknowns)
    throw CaseError(t.path + ":1: holds " + std::to_string(t.header.size() - static_cast<size_t>(first_x)) + " unknowns, the case has " +
                    std::to_string(unknowns) + " (results of another case?)");
  std::vector<FoldCurvePoint> curve;
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const std::vector<double>& row = t.rows[i];
    FoldCurvePoint p;
    p.leg = static_cast<int>(row[static_cast<size_t>(leg)]);
    p.omega = row[static_cast<size_t>(omega)];
    p.parameter = row[static_cast<size_t>(gamma)];
    p.x = read_unknowns(t, i, static_cast<size_t>(first_x), hbm);
    curve.push_back(std::move(p));
  }
  return curve;
}

int run_isolas(const IsolaOptions& o) {
  const auto t0 = Clock::now();
  const double value = parse_number("--at", o.at);
  std::string parameter_name;
  for (const std::string& dir : o.from) {
    const json s = read_summary(dir);
    const std::string name = s.contains("options") && s["options"].contains("tracking") ? s["options"]["tracking"].value("parameter", "") : "";
    if (name.empty()) throw CaseError(dir + "/summary.json: options.tracking.parameter missing (is --from a track result?)");
    if (!parameter_name.empty() && name != parameter_name)
      throw CaseError("--from: " + dir + " tracks '" + name + "', " + o.from.front() + " tracks '" + parameter_name + "'");
    parameter_name = name;
  }
  CaseDefinition c = case_as_in(o.common, o.from.front());
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), parameter_name, "--param");
  std::vector<std::vector<FoldCurvePoint>> curves;
  for (const std::string& dir : o.from) curves.push_back(read_tracking_curve(dir, parameter_name, hbm));
  double lo = value, hi = value;
  for (const auto& curve : curves)
    for (const auto& p : curve) lo = std::min(lo, p.parameter), hi = std::max(hi, p.parameter);
  hbm.set_parameter(parameter, value);
  const FoldScales scales = tracking_scales(hbm, c.nfrc, std::max(hi - lo, 1e-300));

  ensure_directory(o.common.out_dir);
  lock_result_folder(o.common.out_dir);
  json summary = {{"verb", "isolas"}, {"options", options_json(c, hbm)}, {"stop_reason", "running"}};
  summary["options"]["isolas"] = {{"from", o.from}, {"parameter", parameter_name}, {"at", value}};
  write_json_atomically(o.common.out_dir + "/summary.json", summary);

  const std::vector<IsolaCandidate> found = compute_isolas(hbm, parameter, value, curves, scales, c.nfrc, c.outputs, !o.locate_only);
  json crossings = json::array();
  int isolas = 0;
  for (size_t k = 0; k < found.size(); ++k) {
    const IsolaCandidate& f = found[k];
    json j = {{"status", f.status}, {"omega", f.start.omega}, {"converged", f.start.converged}};
    if (f.same_as >= 0) j["same_as"] = f.same_as;
    if (f.start.converged) add_outputs(j, c, record_point(hbm, f.start.x, f.start.omega, c.outputs));
    if (f.status == "isola" || f.status == "open") {
      const std::string name = f.status == "isola" ? "isola_" + std::to_string(++isolas) : "open_" + std::to_string(k + 1);
      const std::string dir = o.common.out_dir + "/" + name;
      ensure_directory(dir);
      CsvAppender branch(dir + "/branch.csv", branch_header(c));
      CsvAppender states(dir + "/states.csv", dof_state_header(hbm));
      std::optional<CsvAppender> stability;
      if (c.nfrc.stability.enabled()) stability.emplace(dir + "/stability.csv", stability_header());
      for (size_t i = 0; i < f.branch.recorded.size(); ++i) {
        branch.append(branch_row(f.branch.recorded[i]));
        if (stability)
          for (const auto& row : stability_rows(static_cast<int>(i), f.branch.recorded[i])) stability->append(row);
        states.append(dof_state_row(hbm, f.branch.continuation.points[i].lambda, f.branch.continuation.points[i].u));
      }
      const auto& s = f.branch.continuation.summary;
      j["folder"] = name;
      j["stop_reason"] = s.stop_reason;
      j["points"] = s.points;
      double omega_min = 1e300, omega_max = -1e300;
      for (const auto& p : f.branch.continuation.points) omega_min = std::min(omega_min, p.lambda), omega_max = std::max(omega_max, p.lambda);
      j["omega_range"] = {omega_min, omega_max};
      int unstable = 0;
      for (const auto& rec : f.branch.recorded) unstable += rec.stable == 0;
      j["unstable_points"] = unstable;
      json special = json::array();
      hbm.set_parameter(parameter, value);
      for (const auto& sp : f.branch.continuation.special_points) {
        json p = {{"type", sp.type}, {"index", sp.index}, {"omega", sp.lambda}, {"located", sp.located}};
        add_outputs(p, c, record_point(hbm, sp.u, sp.lambda, c.outputs));
        special.push_back(p);
      }
      j["special_points"] = special;
      // Each branch folder is a result folder of its own (plot_branch.py, simulate --from).
      json branch_summary = {{"verb", "isolas"},        {"options", options_json(c, hbm)}, {"stop_reason", s.stop_reason},
                             {"points", s.points},       {"special_points", special},       {"outputs", json::array()}};
      for (const auto& out : c.outputs)
        branch_summary["outputs"].push_back({{"name", out.name}, {"dof", c.model.dof_names[static_cast<size_t>(out.dof)]}});
      write_json_atomically(dir + "/summary.json", branch_summary);
    }
    crossings.push_back(j);
  }
  summary["stop_reason"] = "completed";
  summary["crossings"] = crossings;
  summary["isolas"] = isolas;
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  write_json_atomically(o.common.out_dir + "/summary.json", summary);
  if (!o.common.quiet)
    std::fprintf(stderr, "isolas: %zu crossings of %s = %g, %d isolated branches, %.3f s -> %s\n", found.size(), parameter_name.c_str(), value,
                 isolas, summary["timings"]["wall_s"].get<double>(), o.common.out_dir.c_str());
  return 0;
}

void add_track_verbs(CLI::App& app, VerbList& verbs) {
  static TrackOptions track;
  static IsolaOptions isolas;
  CLI::App* t = app.add_subcommand("track", "follow a limit point of a frc result in a second parameter");
  add_common_options(t, track.common);
  t->get_option("--output")->required(false);  // --resume DIR names the folder instead
  // Required unless --resume DIR, which takes them from the stopped run (checked in run_track).
  t->add_option("--from", track.from, "frc result folder holding the limit point");
  t->add_option("--lp", track.lp, "which limit point of --from: LP K counts from 1 in increasing omega, as the figures number them");
  t->add_option("--param", track.param, "the parameter to vary (a name of the case's [parameters], or amplitude)");
  t->add_option("--range", track.range, "LO:HI, the parameter's interval");
  t->add_option("--method", track.method, "bordered (minimally augmented, default) or extended (the paper's system)");
  t->add_option("--resume", track.resume, "continue the stopped track run in this folder (same case and --set)");
  add_time_limit_option(t, track.time_limit);
  verbs.push_back({t, [] { return run_track(track); }});
  CLI::App* i = app.add_subcommand("isolas", "isolated branches at one parameter value, from tracking curves");
  add_common_options(i, isolas.common);
  i->add_option("--from", isolas.from, "track result folder (repeat for several curves)")
      ->required()
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  i->add_option("--at", isolas.at, "the parameter value")->required();
  i->add_flag("--locate-only", isolas.locate_only, "only locate the limit points where the curves cross --at (no branches)");
  verbs.push_back({i, [] { return run_isolas(isolas); }});
}

const VerbRegistrar registrar(add_track_verbs);

}  // namespace

}  // namespace hbtrack::cli
