// `hbtrack modes`: the undamped natural frequencies of a case's (reduced) model; for a blade
// reduced by `hbtrack reduce`, each with its name (1B, 2B, 1T) and the full model's frequency.
#include <cstdio>
#include <numbers>

#include "cli_common.hpp"
#include "full_model_modes.hpp"
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
    const FullModelModes full = full_model_modes(c);
    size_t mode = 0;
    for (const auto& w : report.summary["natural_frequencies"]) {
      const double omega = w.get<double>();
      const std::string name = mode < full.names.size() ? full.names[mode] : "";
      std::string line = "  mode " + std::to_string(mode + 1) + (name.empty() ? ":" : " " + name + ":");
      char numbers[128];
      std::snprintf(numbers, sizeof numbers, " %.4f rad/s (%.3f Hz)", omega, omega / (2.0 * std::numbers::pi));
      line += numbers;
      if (mode < full.frequencies.size()) {
        std::snprintf(numbers, sizeof numbers, ", full model %.4f (%+.3f %%)", full.frequencies[mode],
                      100 * (omega / full.frequencies[mode] - 1));
        line += numbers;
      }
      std::fprintf(stderr, "%s\n", line.c_str());
      ++mode;
    }
    if (!full.reduce_summary.empty())
      std::fprintf(stderr,
                   "modes: these are the reduced model's frequencies; the full model's, which the docs quote (%s: "
                   "full_model), differ by the percentages shown\n",
                   full.reduce_summary.c_str());
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
