// `hbtrack backbone`: the nonlinear mode of a linear mode by the extended periodic motion
// concept (docs/analyses.md): omega and the modal damping ratio against the modal amplitude.
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "hbtrack/analysis/backbone.hpp"
#include "hbtrack/results/backbone_tables.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "result_folder.hpp"
#include "stop_request.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct BackboneCliOptions {
  CommonOptions common;
  std::string mode = "1", range;
  double time_limit = 0;
};

int run_backbone(const BackboneCliOptions& o) {
  const auto t0 = Clock::now();
  BackboneOptions options;
  options.mode = static_cast<int>(parse_integer("--mode", o.mode, 1));
  const size_t colon = o.range.find(':');
  if (colon == std::string::npos) throw CaseError("--range: expected LO:HI (modal amplitudes), got '" + o.range + "'");
  options.amplitude_start = parse_positive("--range", o.range.substr(0, colon));
  options.amplitude_end = parse_positive("--range", o.range.substr(colon + 1));
  if (!(options.amplitude_end > options.amplitude_start)) throw CaseError("--range: must be LO:HI with 0 < LO < HI, got '" + o.range + "'");
  // Every dof is an unknown: the negative modal damping acts on the whole model.
  std::vector<std::string> sets = o.common.sets;
  sets.push_back("harmonic_balance.condensation=\"none\"");
  const CaseDefinition c = load_case(o.common.case_path, sets);
  HarmonicBalance hbm = make_system(c);
  options.continuation = c.nfrc.continuation;
  if (options.mode > c.model.dofs())
    throw CaseError("--mode: " + std::to_string(options.mode) + " is beyond the model's " + std::to_string(c.model.dofs()) + " modes");

  const std::string& dir = o.common.out_dir;
  json summary = {{"verb", "backbone"}, {"options", options_json(c, hbm)}, {"stop_reason", to_string(StopReason::running)}};
  summary["options"]["backbone"] = backbone_options_json(options);
  ensure_directory(dir);
  CsvAppender branch(dir + "/branch.csv", backbone_header(c, hbm.basis().harmonic_numbers()));
  CsvAppender states(dir + "/states.csv", dof_state_header(hbm));
  write_json_atomically(dir + "/summary.json", summary);

  Progress progress(o.common.quiet);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  BackboneResult r;
  try {
    r = compute_backbone(hbm, options, c.outputs, [&](const BranchPoint& p, const BackbonePoint& point, int index) {
      branch.append(backbone_row(point));
      states.append(dof_state_row(hbm, point.omega, point.amplitude * p.u.head(hbm.unknowns())));
      progress.update(index, point.omega, point.recorded, c.outputs);
      return !stop.requested();
    });
  } catch (const std::runtime_error& e) {
    summary["stop_reason"] = to_string(StopReason::no_convergence);
    summary["points"] = 0;
    write_json_atomically(dir + "/summary.json", summary);
    throw RunFailed{e.what()};
  }
  progress.finish();
  const auto& s = r.continuation.summary;
  const std::string stop_reason = to_string(stop.reason(s.stop_reason));
  add_backbone_summary(summary, c, hbm, r);
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", s.wall_s}};
  write_json_atomically(dir + "/summary.json", summary);
  if (!r.continuation.success())
    throw RunFailed{"backbone stopped: " + stop_reason + " after " + std::to_string(s.points) + " points (kept in " + dir + ")"};
  if (!o.common.quiet)
    std::fprintf(stderr, "backbone: mode %d, %d points, omega %.6g -> %.6g, %.3f s -> %s\n", options.mode, s.points, r.points.front().omega,
                 r.points.back().omega, summary["timings"]["wall_s"].get<double>(), dir.c_str());
  return 0;
}

void add_backbone_verb(CLI::App& app, VerbList& verbs) {
  static BackboneCliOptions options;
  CLI::App* command = app.add_subcommand("backbone", "nonlinear mode (EPMC): backbone omega(a) and modal damping ratio");
  add_common_options(command, options.common);
  command->add_option("--mode", options.mode, "linear mode followed, from 1 (default 1)");
  command->add_option("--range", options.range, "LO:HI modal amplitudes (sqrt(x1' M x1)); LO near the linear mode")->required();
  add_time_limit_option(command, options.time_limit);
  verbs.push_back({command, [] { return run_backbone(options); }});
}

const VerbRegistrar registrar(add_backbone_verb);

}  // namespace

}  // namespace hbtrack::cli
