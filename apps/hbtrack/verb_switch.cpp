// `hbtrack switch`: the branch crossing an NFRC at one of its branch points (BP), from the null
// space of the extended Jacobian there, or the period-doubled branch born at a period doubling
// (PD), the same switch in the harmonic balance at omega / 2 (docs/analyses.md). Writes the frc
// contract: the new branch in one piece, from the end of the leg that went back through the BP
// to the end of the leg that went away from it (at a PD: from this PD to the band's other one).
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "hbtrack/analysis/branch_switching.hpp"
#include "hbtrack/analysis/period_doubling.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "result_folder.hpp"

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
  const json& special = from["special_points"];
  if (point > static_cast<long>(special.size()))
    throw CaseError("--point: " + std::to_string(point) + " is beyond the " + std::to_string(special.size()) + " special points of " + path);
  const json& sp = special[static_cast<size_t>(point - 1)];
  const std::string type = sp.value("type", "");
  if (type != "BP" && type != "PD")
    throw CaseError("--point: special point " + std::to_string(point) + " of " + path + " is a " + type +
                    "; switch follows the new branch of a BP or the period-doubled branch of a PD");
  // At a PD the new branch is a solution of the harmonic balance at omega / 2.
  CaseDefinition c = period_one;
  if (type == "PD") {
    if (period_one.harmonic_balance.subharmonic != 1)
      throw CaseError("--point: " + o.from + " is already a period-doubled branch (subharmonic " +
                      std::to_string(period_one.harmonic_balance.subharmonic) + "); switch from a period-T NFRC");
    c.harmonic_balance = period_doubled_options(period_one.harmonic_balance);
  }
  HarmonicBalance system = make_system(c);
  const HbmState bp = read_hbm_state(o.from + "/special_states.csv", point - 1, hbm);
  const long row = sp.value("index", -1L);
  const long rows = static_cast<long>(read_csv_table(o.from + "/states.csv").rows.size());
  if (row < 0 || row >= rows) throw CaseError(path + ": special point " + std::to_string(point) + ": index out of the branch");
  const HbmState before = read_hbm_state(o.from + "/states.csv", std::max(row - 1, 0L), hbm);
  const HbmState after = read_hbm_state(o.from + "/states.csv", std::min(row + 1, rows - 1), hbm);
  if (bp.x.size() != hbm.unknowns() || before.x.size() != hbm.unknowns())
    throw CaseError(o.from + ": its states hold " + std::to_string(bp.x.size()) + " unknowns, the case has " + std::to_string(hbm.unknowns()) +
                    " (results of another case?)");
  Eigen::VectorXd known(hbm.unknowns() + 1);
  known.head(hbm.unknowns()) = after.x - before.x;
  known(hbm.unknowns()) = after.omega - before.omega;

  const std::string& dir = o.common.out_dir;
  ensure_directory(dir);
  json summary = {{"verb", "switch"}, {"options", options_json(c, system)}, {"stop_reason", to_string(StopReason::running)}};
  summary["options"]["switch"] = {{"from", o.from}, {"point", point}, {"type", type}, {"omega", bp.omega}};
  write_json_atomically(dir + "/summary.json", summary);
  SwitchedBranch s;
  try {
    s = type == "PD" ? switch_at_period_doubling(system, hbm.basis(), c.nfrc, c.outputs, bp.x, bp.omega, known)
                     : switch_at_branch_point(system, c.nfrc, c.outputs, bp.x, bp.omega, known);
  } catch (const std::runtime_error& e) {
    summary["stop_reason"] = to_string(StopReason::no_convergence);
    write_json_atomically(dir + "/summary.json", summary);
    throw RunFailed{e.what()};
  }
  // One piece: the `through` leg reversed, then the `away` leg without its first point (shared).
  CsvAppender branch(dir + "/branch.csv", branch_header(c));
  CsvAppender states(dir + "/states.csv", dof_state_header(system));
  const int through = static_cast<int>(s.through.recorded.size());
  for (int i = through - 1; i >= 0; --i) {
    branch.append(branch_row(s.through.recorded[static_cast<size_t>(i)]));
    states.append(dof_state_row(system, s.through.continuation.points[static_cast<size_t>(i)].lambda, s.through.continuation.points[static_cast<size_t>(i)].u));
  }
  const int shift = through > 0 ? through - 1 : 0;  // row of the away leg's point i: shift + i
  for (size_t i = through > 0 ? 1 : 0; i < s.away.recorded.size(); ++i) {
    branch.append(branch_row(s.away.recorded[i]));
    states.append(dof_state_row(system, s.away.continuation.points[i].lambda, s.away.continuation.points[i].u));
  }
  json points = json::array();
  CsvAppender special_states(dir + "/special_states.csv", dof_state_header(system));
  for (const auto* leg : {&s.through, &s.away})
    for (const auto& p : leg->continuation.special_points) {
      const int index = leg == &s.through ? through - 1 - p.index : shift + p.index;
      json j = {{"type", p.type}, {"index", index}, {"omega", p.lambda}, {"located", p.located}};
      j["parameters"] = summary["options"]["parameters"];
      add_outputs(j, c, record_point(system, p.u, p.lambda, c.outputs));
      points.push_back(j);
      special_states.append(dof_state_row(system, p.lambda, p.u));
    }
  const auto& a = s.away.continuation.summary;
  const auto& b = s.through.continuation.summary;
  summary["special_points"] = points;
  summary["outputs"] = outputs_json(c);
  summary["points"] = shift + static_cast<int>(s.away.recorded.size());
  summary["newton_iterations"] = a.newton_iterations + b.newton_iterations;
  summary["failed_steps"] = a.failed_steps + b.failed_steps;
  summary["step_halvings"] = a.step_halvings + b.step_halvings;
  summary["legs"] = {{{"name", "through"}, {"stop_reason", to_string(b.stop_reason)}, {"points", b.points}},
                     {{"name", "away"}, {"stop_reason", to_string(a.stop_reason)}, {"points", a.points}}};
  // A period-doubled leg ends where it rejoins the period-T branch (at a PD of the band).
  const bool away_ok = s.away.continuation.success() || a.stop_reason == StopReason::rejoined;
  const bool ok = away_ok && (s.through.continuation.success() || b.stop_reason == StopReason::rejoined);
  summary["stop_reason"] = to_string(ok ? StopReason::completed : (away_ok ? b.stop_reason : a.stop_reason));
  summary["timings"] = {{"wall_s", seconds_since(t0)}};
  write_json_atomically(dir + "/summary.json", summary);
  if (!ok) throw RunFailed{"switch: a leg stopped: " + summary["stop_reason"].get<std::string>() + " (kept in " + dir + ")"};
  if (!o.common.quiet)
    std::fprintf(stderr, "switch: %d points, %d special points, %.3f s -> %s\n", summary["points"].get<int>(), static_cast<int>(points.size()),
                 summary["timings"]["wall_s"].get<double>(), dir.c_str());
  return 0;
}

void add_switch_verb(CLI::App& app, VerbList& verbs) {
  static SwitchOptions options;
  CLI::App* command =
      app.add_subcommand("switch", "the branch crossing a frc result at one of its branch points (BP), or the period-doubled branch of a PD");
  add_common_options(command, options.common);
  command->add_option("--from", options.from, "a frc result folder")->required();
  command->add_option("--point", options.point, "its special point (from 1, as in summary.json), a BP or a PD")->required();
  verbs.push_back({command, [] { return run_switch(options); }});
}

const VerbRegistrar registrar(add_switch_verb);

}  // namespace

}  // namespace hbtrack::cli
