// `hbtrack switch`: the branch crossing an NFRC at one of its branch points (BP), from the null
// space of the extended Jacobian there, or the period-doubled branch born at a period doubling
// (PD), the same switch in the harmonic balance at omega / 2 (docs/analyses.md). Writes the frc
// contract: the new branch in one piece, from the end of the leg that went back through the BP
// to the end of the leg that went away from it (at a PD: from this PD to the band's other one).
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "cli_monitor.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "hbtrack/runs/switch_branch.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct SwitchOptions {
  CommonOptions common;
  std::string from, point;
};

int run_switch(const SwitchOptions& o) {
  const auto t0 = Clock::now();
  const long point = parse_integer("--point", o.point, 1);
  const CaseDefinition plain = load_case(o.common.case_path, o.common.sets);
  std::vector<std::string> overrides = hbm_overrides(o.from, plain);
  overrides.insert(overrides.end(), o.common.sets.begin(), o.common.sets.end());  // --set wins
  const CaseDefinition period_one = load_case(o.common.case_path, overrides);
  HarmonicBalance hbm = make_system(period_one);

  const json from = read_summary(o.from);
  const std::string path = o.from + "/summary.json";
  if (!from.contains("special_points") || !from["special_points"].is_array() || from.value("verb", "") != "frc")
    throw CaseError(path + ": special_points missing (is --from a frc result?)");
  const long rows = static_cast<long>(read_csv_table(o.from + "/states.csv").rows.size());
  const runs::SwitchPoint at = runs::switch_point(from["special_points"], point, static_cast<size_t>(rows), {"--point", path});
  if (at.type == SpecialPointType::period_doubling && period_one.harmonic_balance.subharmonic != 1)
    throw CaseError("--point: " + o.from + " is already a period-doubled branch (subharmonic " +
                    std::to_string(period_one.harmonic_balance.subharmonic) + "); switch from a period-T NFRC");
  const auto state = [&](const std::string& file, size_t r) {
    const HbmState s = read_hbm_state(o.from + "/" + file, static_cast<long>(r), hbm);
    return runs::StartPoint{s.omega, s.x, o.from + "/" + file};
  };
  runs::SwitchOptions run{at.type,
                          point,
                          state("special_states.csv", at.special_row),
                          state("states.csv", at.before_row),
                          state("states.csv", at.after_row),
                          {{"from", o.from}}};
  ResultFolderSink sink(o.common.out_dir);
  Progress progress(o.common.quiet);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(0);
  CliMonitor monitor(progress, stop, period_one.outputs);
  runs::RunReport report;
  try {
    report = runs::switch_branch(period_one, run, sink, monitor);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CaseError*>(&e) || dynamic_cast<const WriteFailed*>(&e)) throw;  // exit 2, 3
    throw RunFailed{e.what()};
  }
  progress.finish();
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.common.quiet)
    std::fprintf(stderr, "switch: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
  return 0;
}

void add_switch_verb(CLI::App& app, VerbList& verbs) {
  static SwitchOptions options;
  CLI::App* command = app.add_subcommand(
      "switch", "the branch crossing a frc result at one of its branch points (BP), or the period-doubled branch of a PD");
  add_common_options(command, options.common);
  command->add_option("--from", options.from, "a frc result folder")->required();
  command->add_option("--point", options.point, "its special point (from 1, as in summary.json), a BP or a PD")->required();
  verbs.push_back({command, [] { return run_switch(options); }});
}

const VerbRegistrar switch_registrar(add_switch_verb);

}  // namespace

}  // namespace hbtrack::cli
