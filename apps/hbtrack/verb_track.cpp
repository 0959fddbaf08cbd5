// `hbtrack track`: a limit point (or NS or PD point) of a frc result followed in a second parameter;
// `hbtrack isolas`: the isolated branches a tracking curve reveals at one parameter value.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "cli_common.hpp"
#include "cli_monitor.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "hbtrack/runs/isolas.hpp"
#include "hbtrack/runs/track.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"
#include "special_point_start.hpp"
#include "resume_command.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct TrackOptions {
  CommonOptions common;
  std::string from, lp, ns, pd, param, range, method;  // method: bordered unless given (or resumed)
  std::string resume;                                  // a stopped track result folder to continue
  double time_limit = 0;                               // seconds, 0 for none
};

// --resume DIR: the stopped run's --from, --lp, --param, --range and --method, where not given
// again (given ones must agree: the checkpoint's settings are compared later).
void take_options_of_stopped_run(TrackOptions& o) {
  const json summary = read_summary(o.resume);
  if (!summary.contains("options") || !summary["options"].contains("tracking") || !summary["options"]["tracking"].is_object())
    throw CaseError("--resume: " + o.resume + "/summary.json: options.tracking missing (is it a track result?)");
  const json& t = summary["options"]["tracking"];
  // Before lp_order, --lp counted in summary.json's order: the same number may name another LP.
  if (t.contains("lp") && !t.contains("lp_order"))
    throw CaseError("--resume: " + o.resume +
                    "/summary.json: options.tracking.lp_order missing: written when --lp counted limit points "
                    "in the NFRC's order, not in increasing omega; run the tracking again");
  try {
    if (o.from.empty()) o.from = t.at("from").get<std::string>();
    const bool given = !o.lp.empty() || !o.ns.empty() || !o.pd.empty();
    if (!given && t.contains("ns")) o.ns = std::to_string(t.at("ns").get<long>());
    if (!given && t.contains("pd")) o.pd = std::to_string(t.at("pd").get<long>());
    if (!given && o.ns.empty() && o.pd.empty()) o.lp = std::to_string(t.at("lp").get<long>());
    if (o.param.empty()) o.param = t.at("parameter").get<std::string>();
    if (o.method.empty()) o.method = t.at("method").get<std::string>();
    if (o.range.empty())
      o.range = number_text(t.at("range").at(0).get<double>(), 17) + ":" + number_text(t.at("range").at(1).get<double>(), 17);
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

// Which of --lp, --ns, --pd was given (exactly one): its flag, value and what it tracks.
struct StartFlag {
  std::string flag, value;
  TrackedPoint tracked;
};
StartFlag start_flag(const TrackOptions& o) {
  std::vector<StartFlag> given;
  if (!o.lp.empty()) given.push_back({"--lp", o.lp, TrackedPoint::limit_point});
  if (!o.ns.empty()) given.push_back({"--ns", o.ns, TrackedPoint::neimark_sacker});
  if (!o.pd.empty()) given.push_back({"--pd", o.pd, TrackedPoint::period_doubling});
  if (given.empty()) throw CaseError("--lp, --ns or --pd is required (or --resume DIR)");
  if (given.size() > 1) throw CaseError(given[0].flag + " and " + given[1].flag + ": give one point to track");
  return given.front();
}

int run_track(TrackOptions o) {
  const auto t0 = Clock::now();
  if (!o.resume.empty()) {
    if (!o.common.out_dir.empty() && o.common.out_dir != o.resume)
      throw CaseError("--resume: continues in its own folder, give no other -o");
    o.common.out_dir = o.resume;
    take_options_of_stopped_run(o);
  }
  if (o.common.out_dir.empty()) throw CaseError("--output is required (or --resume DIR)");
  for (const auto& [flag, value] : {std::pair{"--from", &o.from}, {"--param", &o.param}, {"--range", &o.range}})
    if (value->empty()) throw CaseError(std::string(flag) + " is required (or --resume DIR)");
  const StartFlag point = start_flag(o);
  if (point.tracked != TrackedPoint::limit_point && !o.method.empty() && o.method != "bordered")
    throw CaseError("--method: " + point.flag + " tracks on the bordered Hill pencil only, got '" + o.method + "'");
  if (o.method.empty()) o.method = "bordered";
  const long k = parse_integer(point.flag, point.value, 1);
  const size_t colon = o.range.find(':');
  if (colon == std::string::npos) throw CaseError("--range: expected LO:HI, got '" + o.range + "'");
  const double tracking_min = parse_number("--range", o.range.substr(0, colon));
  const double tracking_max = parse_number("--range", o.range.substr(colon + 1));
  if (!(tracking_min < tracking_max)) throw CaseError("--range: must be LO:HI with LO < HI, got '" + o.range + "'");
  const TrackingMethod method = parse_flag_choice<TrackingMethod>("--method", o.method);

  const CaseDefinition c = case_as_in(o.common, o.from);
  runs::TrackOptions run;
  run.parameter = o.param;
  run.parameter_min = tracking_min;
  run.parameter_max = tracking_max;
  run.method = method;
  run.tracked = point.tracked;
  const HbmState start = starting_point(o.from, special_point_type(point.tracked), point.flag, k, make_system(c));
  run.start = runs::StartPoint{start.omega, start.x, o.from + "/special_states.csv"};
  const std::string key = point.flag.substr(2);  // lp, ns, pd
  run.origin = {{"from", o.from}, {key, k}, {key + "_order", "omega"}};
  ResultFolderSink sink(o.common.out_dir, !o.resume.empty());
  const double start_value = c.parameters.find(o.param) >= 0 ? c.parameters.value(c.parameters.find(o.param)) : 0.0;
  Progress progress(o.common.quiet, o.param, tracking_min, tracking_max, start_value);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  CliMonitor monitor(progress, stop, c.outputs);
  runs::RunReport report;
  try {
    report = runs::track(c, run, sink, monitor);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CaseError*>(&e)) throw;
    throw RunFailed{e.what()};
  }
  progress.finish();
  for (const auto& w : report.summary["warnings"]) std::fprintf(stderr, "track: warning: %s\n", w.get<std::string>().c_str());
  if (!report.success())
    throw RunFailed{report.failure, resume_advice(report.summary.value("stop_reason", ""), resume_command(o.common.out_dir))};
  if (!o.common.quiet) std::fprintf(stderr, "track: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
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
    const std::string name =
        s.contains("options") && s["options"].contains("tracking") ? s["options"]["tracking"].value("parameter", "") : "";
    if (name.empty()) throw CaseError(dir + "/summary.json: options.tracking.parameter missing (is --from a track result?)");
    // An NS (PD) curve's points are not limit points: no branch goes through them as a fold.
    const std::string point = s["options"]["tracking"].value("point", to_string(SpecialPointType::limit_point));
    if (parse_tracked_point(point, dir + "/summary.json: options.tracking.point") != TrackedPoint::limit_point)
      throw CaseError("--from: " + dir + " is a curve of " + point + " points; isolas takes limit-point curves (track --lp K)");
    if (!parameter_name.empty() && name != parameter_name)
      throw CaseError("--from: " + dir + " tracks '" + name + "', " + o.from.front() + " tracks '" + parameter_name + "'");
    parameter_name = name;
  }
  const CaseDefinition c = case_as_in(o.common, o.from.front());
  runs::IsolaOptions run;
  run.parameter = parameter_name;
  run.at = value;
  run.locate_only = o.locate_only;
  run.origin = {{"from", o.from}};
  {
    const HarmonicBalance hbm = make_system(c);
    for (const std::string& dir : o.from) run.curves.push_back(read_tracking_curve(dir, parameter_name, hbm));
  }
  ResultFolderSink sink(o.common.out_dir);
  Progress progress(o.common.quiet);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(0);
  CliMonitor monitor(progress, stop, c.outputs);
  const runs::RunReport report = runs::isolas(c, run, sink, monitor);
  progress.finish();
  if (!o.common.quiet)
    std::fprintf(stderr, "isolas: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
  return 0;
}

void add_track_verbs(CLI::App& app, VerbList& verbs) {
  static TrackOptions track;
  static IsolaOptions isolas;
  CLI::App* t = app.add_subcommand("track", "follow a limit point (NS, PD point) of a frc result in a second parameter");
  add_common_options(t, track.common);
  t->get_option("--output")->required(false);  // --resume DIR names the folder instead
  // Required unless --resume DIR, which takes them from the stopped run (checked in run_track).
  t->add_option("--from", track.from, "frc result folder holding the limit point");
  t->add_option("--lp", track.lp, "which limit point of --from: LP K counts from 1 in increasing omega, as the figures number them");
  t->add_option("--ns", track.ns, "or which Neimark-Sacker point of --from (from 1, in increasing omega): the NS curve");
  t->add_option("--pd", track.pd, "or which period-doubling point of --from (from 1, in increasing omega): the PD curve");
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

const VerbRegistrar track_registrar(add_track_verbs);

}  // namespace

}  // namespace hbtrack::cli
