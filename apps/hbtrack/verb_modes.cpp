// `hbtrack modes`: the undamped natural frequencies of a case's (reduced) model.
#include <cstdio>
#include <numbers>

#include "cli_common.hpp"
#include "hbtrack/runs/modes.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

namespace {

int run_modes(const CommonOptions& o, int count) {
  if (count < 1) throw CaseError("--count: must be >= 1");
  const CaseDefinition c = load_case(o.case_path, o.sets);
  ResultFolderSink sink(o.out_dir);
  const runs::RunReport report = runs::modes(c, count, sink);
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.quiet) {
    std::fprintf(stderr, "modes: %s -> %s\n", report.brief.c_str(), o.out_dir.c_str());
    int mode = 0;
    for (const auto& w : report.summary["natural_frequencies"]) {
      const double omega = w.get<double>();
      std::fprintf(stderr, "  mode %d: %.4f rad/s (%.3f Hz)\n", ++mode, omega, omega / (2.0 * std::numbers::pi));
    }
  }
  return 0;
}

void add_modes_verbs(CLI::App& app, VerbList& verbs) {
  static CommonOptions options;
  static int count = 10;
  CLI::App* modes = app.add_subcommand("modes", "natural frequencies (rad/s) of the case's linear model");
  add_common_options(modes, options);
  modes->add_option("--count", count, "lowest modes reported (default 10)");
  verbs.push_back({modes, [] { return run_modes(options, count); }});
}

const VerbRegistrar modes_registrar(add_modes_verbs);

}  // namespace

}  // namespace hbtrack::cli
