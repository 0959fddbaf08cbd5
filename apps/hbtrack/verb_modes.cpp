// `hbtrack modes`: the undamped natural frequencies of a case's (reduced) model.
#include <chrono>
#include <cstdio>
#include <numbers>

#include "cli_common.hpp"
#include "hbtrack/model/damping.hpp"
#include "hbtrack/results/results_writer.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

int run_modes(const CommonOptions& o, int count) {
  const auto t0 = Clock::now();
  if (count < 1) throw CaseError("--count: must be >= 1");
  const CaseDefinition c = load_case(o.case_path, o.sets);
  NormalModes modes;
  try {
    modes = normal_modes(c.model.mass, c.model.stiffness);
  } catch (const std::runtime_error& e) {
    throw RunFailed{e.what()};
  }
  const Eigen::Index kept = std::min<Eigen::Index>(count, modes.frequencies.size());
  json frequencies = json::array(), dominant = json::array();
  for (Eigen::Index r = 0; r < kept; ++r) {
    frequencies.push_back(modes.frequencies(r));
    // The dof that moves most in this mass-normalised mode: a quick way to tell modes apart.
    Eigen::Index largest = 0;
    modes.shapes.col(r).cwiseAbs().maxCoeff(&largest);
    dominant.push_back(c.model.dof_names[static_cast<size_t>(largest)]);
  }
  ensure_directory(o.out_dir);
  json summary = {{"verb", "modes"},
                  {"case", c.path},
                  {"dofs", c.model.dofs()},
                  {"natural_frequencies", frequencies},
                  {"dominant_dofs", dominant},
                  {"timings", {{"wall_s", std::chrono::duration<double>(Clock::now() - t0).count()}}}};
  write_json_atomically(o.out_dir + "/summary.json", summary);
  if (!o.quiet) {
    std::fprintf(stderr, "modes: %lld of %d dofs -> %s\n", static_cast<long long>(kept), c.model.dofs(), o.out_dir.c_str());
    for (Eigen::Index r = 0; r < kept; ++r)
      std::fprintf(stderr, "  mode %lld: %.4f rad/s (%.3f Hz)\n", static_cast<long long>(r + 1), modes.frequencies(r), modes.frequencies(r) / (2.0 * std::numbers::pi));
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

const VerbRegistrar registrar(add_modes_verbs);

}  // namespace

}  // namespace hbtrack::cli
