// `hbtrack modes`: the undamped natural frequencies of a case's (reduced) model; for a blade
// reduced by `hbtrack reduce`, each with its name (1B, 2B, 1T) and the full model's frequency.
#include <cstdio>
#include <numbers>

#include "cli_common.hpp"
#include "full_model_modes.hpp"
#include "hbtrack/runs/campbell.hpp"
#include "hbtrack/runs/modes.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

namespace {

// --speeds: the Campbell diagram, campbell.csv.
int run_campbell(const CommonOptions& o, const CaseDefinition& c, int count, const std::string& speeds, int engine_orders) {
  runs::CampbellOptions options;
  options.speeds = runs::parse_speeds(speeds, "--speeds");
  options.count = count;
  options.names = full_model_modes(c).names;
  if (engine_orders < 0) throw CaseError("--engine-orders: must be >= 0");
  options.engine_orders = engine_orders;
  ResultFolderSink sink(o.out_dir);
  const runs::RunReport report = runs::campbell(c, options, sink);
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.quiet) {
    std::fprintf(stderr, "modes: Campbell diagram, %s -> %s/campbell.csv\n", report.brief.c_str(), o.out_dir.c_str());
    const auto& s = report.summary;
    for (size_t j = 0; j < s["mode_names"].size(); ++j) {
      const double w0 = s["frequencies_at_lowest_speed"][j].get<double>(), w1 = s["frequencies_at_highest_speed"][j].get<double>();
      std::fprintf(stderr, "  %-7s %10.2f rad/s at %.1f rad/s -> %10.2f at %.1f (%+.2f %%)\n",
                   s["mode_names"][j].get<std::string>().c_str(), w0, s["speeds"]["min"].get<double>(), w1,
                   s["speeds"]["max"].get<double>(), 100 * (w1 / w0 - 1));
    }
    for (const auto& x : s["engine_order_crossings"])
      std::fprintf(stderr, "  %s meets engine order %d at %.1f rad/s (%.0f rpm)\n", x["mode"].get<std::string>().c_str(),
                   x["engine_order"].get<int>(), x["speed"].get<double>(), x["speed"].get<double>() * 30 / std::numbers::pi);
  }
  return 0;
}

int run_modes(const CommonOptions& o, int count, const std::string& speeds, int engine_orders) {
  if (count < 1) throw CaseError("--count: must be >= 1");
  const CaseDefinition c = load_case(o.case_path, o.sets);
  if (!speeds.empty()) return run_campbell(o, c, count, speeds, engine_orders);
  ResultFolderSink sink(o.out_dir);
  const runs::RunReport report = runs::modes(c, count, sink);
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.quiet) {
    std::fprintf(stderr, "modes: %s -> %s\n", report.brief.c_str(), o.out_dir.c_str());
    FullModelModes full = full_model_modes(c);
    if (c.rotation) {
      // K(Omega): the full model's frequencies at rest are not these modes' references.
      std::fprintf(stderr, "modes: at %.6g rad/s ([rotation] speed), K + Omega^2 (Kg1 - Mspin), without G (Campbell: --speeds)\n",
                   c.rotation->speed);
      full.frequencies.clear();
      full.reduce_summary.clear();
    }
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
  static std::string speeds;
  static int engine_orders = 8;
  CLI::App* modes = app.add_subcommand("modes", "natural frequencies (rad/s) of the case's linear model");
  add_common_options(modes, options);
  modes->add_option("--count", count, "lowest modes reported (default 10)");
  modes->add_option("--speeds", speeds,
                    "LO:HI:N: the Campbell diagram of a case with [rotation], N speeds (rad/s) from LO to HI, into campbell.csv");
  modes->add_option("--engine-orders", engine_orders, "with --speeds: report the crossings with k x speed, k = 1 .. K (default 8)");
  verbs.push_back({modes, [] { return run_modes(options, count, speeds, engine_orders); }});
}

const VerbRegistrar modes_registrar(add_modes_verbs);

}  // namespace

}  // namespace hbtrack::cli
