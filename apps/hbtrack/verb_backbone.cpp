// `hbtrack backbone`: the nonlinear mode of a linear mode by the extended periodic motion
// concept (docs/analyses.md): omega and the modal damping ratio against the modal amplitude.
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "cli_monitor.hpp"
#include "hbtrack/runs/backbone.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

namespace {

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
  const CaseDefinition c = load_case(o.common.case_path, o.common.sets);
  ResultFolderSink sink(o.common.out_dir);
  Progress progress(o.common.quiet);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  CliMonitor monitor(progress, stop, c.outputs);
  runs::RunReport report;
  try {
    report = runs::backbone(c, options, sink, monitor);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CaseError*>(&e)) throw;
    throw RunFailed{e.what()};
  }
  progress.finish();
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.common.quiet)
    std::fprintf(stderr, "backbone: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
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

const VerbRegistrar backbone_registrar(add_backbone_verb);

}  // namespace

}  // namespace hbtrack::cli
