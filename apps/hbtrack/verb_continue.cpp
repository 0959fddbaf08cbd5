// `hbtrack continue`: the periodic solution followed in a named parameter at a fixed frequency
// (docs/analyses.md). Writes the frc contract, with the parameter as a column of branch.csv.
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "cli_monitor.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/runs/parameter_branch.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

namespace {

struct ContinueOptions {
  CommonOptions common;
  std::string param, omega, range;
  double time_limit = 0;
};

int run_continue(const ContinueOptions& o) {
  const auto t0 = Clock::now();
  const double omega = parse_positive("--omega", o.omega);
  const size_t colon = o.range.find(':');
  if (colon == std::string::npos) throw CaseError("--range: expected LO:HI, got '" + o.range + "'");
  const double start = parse_number("--range", o.range.substr(0, colon));
  const double end = parse_number("--range", o.range.substr(colon + 1));
  if (start == end) throw CaseError("--range: LO and HI must differ, got '" + o.range + "'");
  const CaseDefinition c = load_case(o.common.case_path, o.common.sets);
  ResultFolderSink sink(o.common.out_dir);
  Progress progress(o.common.quiet);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  CliMonitor monitor(progress, stop, c.outputs);
  runs::RunReport report;
  try {
    report = runs::continue_in_parameter(c, {o.param, omega, start, end}, sink, monitor);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CaseError*>(&e) || dynamic_cast<const WriteFailed*>(&e)) throw;  // exit 2, 3
    throw RunFailed{e.what()};
  }
  progress.finish();
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.common.quiet)
    std::fprintf(stderr, "continue: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
  return 0;
}

void add_continue_verb(CLI::App& app, VerbList& verbs) {
  static ContinueOptions options;
  CLI::App* command = app.add_subcommand("continue", "the periodic solution followed in a named parameter at a fixed omega");
  add_common_options(command, options.common);
  command->add_option("--param", options.param, "the parameter to follow (amplitude, mu, any [parameters] name)")->required();
  command->add_option("--omega", options.omega, "forcing frequency (rad/s), fixed")->required();
  command->add_option("--range", options.range, "LO:HI, from the solution at LO towards HI")->required();
  add_time_limit_option(command, options.time_limit);
  verbs.push_back({command, [] { return run_continue(options); }});
}

const VerbRegistrar continue_registrar(add_continue_verb);

}  // namespace

}  // namespace hbtrack::cli
