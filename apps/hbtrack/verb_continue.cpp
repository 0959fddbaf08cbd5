// `hbtrack continue`: the periodic solution followed in a named parameter at a fixed frequency
// (docs/analyses.md). Writes the frc contract, with the parameter as a column of branch.csv.
#include <cmath>
#include <cstdio>

#include "cli_common.hpp"
#include "hbtrack/analysis/parameter_continuation.hpp"
#include "hbtrack/results/parameter_tables.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/results/state_columns.hpp"
#include "result_folder.hpp"
#include "stop_request.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

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
  HarmonicBalance hbm = make_system(c);
  const int parameter = parameter_index(hbm.parameters(), o.param, "--param");

  const std::string& dir = o.common.out_dir;
  json summary = {{"verb", "continue"}, {"options", options_json(c, hbm)}, {"stop_reason", "running"}};
  summary["options"]["continue"] = parameter_continuation_options(o.param, omega, start, end);
  ensure_directory(dir);
  CsvAppender branch(dir + "/branch.csv", parameter_branch_header(c, o.param));
  CsvAppender states(dir + "/states.csv", dof_state_header(hbm));
  write_json_atomically(dir + "/summary.json", summary);

  Progress progress(o.common.quiet);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  const double nominal = hbm.parameters().value(parameter);
  ParameterBranchResult r;
  try {
    r = continue_in_parameter(hbm, parameter, omega, start, end, c.nfrc, c.outputs,
                              [&](const BranchPoint& p, const ParameterBranchPoint& point, int index) {
                                branch.append(parameter_branch_row(point));
                                states.append(dof_state_row(hbm, omega, p.u, parameter, p.lambda));
                                progress.update(index, p.lambda, point.recorded, c.outputs);
                                return !stop.requested();
                              });
  } catch (const std::runtime_error& e) {
    summary["stop_reason"] = "no_convergence";
    summary["points"] = 0;
    write_json_atomically(dir + "/summary.json", summary);
    throw RunFailed{e.what()};
  }
  progress.finish();
  hbm.set_parameter(parameter, nominal);
  const auto& s = r.continuation.summary;
  const std::string stop_reason = stop.reason(s.stop_reason);
  add_parameter_branch_summary(summary, c, hbm, r, parameter);
  summary["stop_reason"] = stop_reason;
  summary["timings"] = {{"wall_s", seconds_since(t0)}, {"continuation_s", s.wall_s}};
  CsvAppender special_states(dir + "/special_states.csv", dof_state_header(hbm));
  // At each point's own parameter value: the condensed dofs' recovery depends on it.
  for (const auto& sp : r.continuation.special_points) special_states.append(dof_state_row(hbm, omega, sp.u, parameter, sp.lambda));
  write_json_atomically(dir + "/summary.json", summary);
  if (!r.continuation.success())
    throw RunFailed{"continuation stopped: " + stop_reason + " after " + std::to_string(s.points) + " points (kept in " + dir + ")"};
  if (!o.common.quiet)
    std::fprintf(stderr, "continue: %d points, %d special points, %d Newton iterations, %.3f s -> %s\n", s.points,
                 static_cast<int>(r.continuation.special_points.size()), s.newton_iterations, summary["timings"]["wall_s"].get<double>(),
                 dir.c_str());
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

const VerbRegistrar registrar(add_continue_verb);

}  // namespace

}  // namespace hbtrack::cli
