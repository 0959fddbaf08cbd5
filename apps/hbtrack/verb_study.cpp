// `hbtrack study`: the paper's whole analysis of one case, as the verbs a user would run by hand,
// each a child process writing its own result folder under DIR (independent ones side by side, on
// this machine or on MPI ranks: task_runner.hpp):
//   nfrc/                 the nominal NFRC with stability
//   backbone_modeK/       with [study] backbone: the nonlinear mode K (study_branches.hpp)
//   switch_bpK/, _pdK/    with [study] switch: the branch born at the NFRC's special point K
//   torus_nsK/            with [study] torus: the torus born at NS point K, across its band
//                         (study_tori.hpp)
//   track_P_lpK/          limit point K followed in parameter P (the case's [study] section)
//   track_P_nsK/, _pdK/   with [study] track_ns_pd: NS (PD) point K followed in P
//   validate_P_J/         an NFRC at a parameter value next to each extremum of the P curves
//   crossings_P_J/        the limit points of the tracking curves at that value, located
//   isolas_P_J/           the branches through the crossings no validation NFRC holds
//   simulate/             time integration from the stable resonance point of the NFRC
//   simulate_isola/       time integration from the middle of the stable stretch of the isolas'
//                         largest stable output (study_comparisons.hpp)
//   converged/            with [study] convergence: the NFRC and tracking curves at more H, N
//   figures/, index.md    the figures and a page with the numbers (study_report.cpp)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "child_process.hpp"
#include "cli_common.hpp"
#include "folder_lock.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/util/stop_reason.hpp"
#include "result_folder.hpp"
#include "resume_command.hpp"
#include "step_progress.hpp"
#include "study.hpp"
#include "study_branches.hpp"
#include "study_comparisons.hpp"
#include "study_curves.hpp"
#include "study_figures_step.hpp"
#include "study_checks.hpp"
#include "study_report.hpp"
#include "study_plan.hpp"
#include "study_resume.hpp"
#include "study_tori.hpp"
#include "task_runner.hpp"

namespace hbtrack::cli {

using nlohmann::json;

int Study::run() {
  const auto t0 = Clock::now();
  const bool resuming = !o_.resume.empty();
  if (resuming && !std::filesystem::is_directory(dir_)) throw CaseError("--resume: " + dir_ + ": no such folder");
  ensure_directory(dir_);
  lock_result_folder(dir_);
  const json settings = study_settings(o_.common.case_path, o_.common.sets, o_.only);
  if (resuming) previous_ = steps_to_resume(dir_, settings);
  summary_ = {{"verb", "study"},         {"case", o_.common.case_path},
              {"jobs", runner_.slots()}, {"runner", runner_.description()},
              {"settings", settings},    {"stop_reason", to_string(StopReason::running)},
              {"steps", json::array()}};
  if (resuming) summary_["resumed_steps"] = 0;
  save();
  const bool ok = nominal() && branches() && tracking() && ns_pd_tracking() && validation_and_simulation() && added_families() &&
                  isolas() && isola_simulation_and_convergence();
  // Only the parameters tracking reached: a study stopped at its nominal NFRC has none (a
  // null entry here made the checks and the page fail on "cannot use value() with null").
  for (const StudyTrack& t : tracked_)
    if (const auto e = entries_.find(t.parameter); e != entries_.end()) summary_["tracking"].push_back(e->second);
  save();  // the figures script reads it
  figures();
  const json failed = failed_checks(summary_);
  summary_["failed_checks"] = failed;
  summary_["stop_reason"] = !ok ? stop_reason_ : to_string(failed.empty() ? StopReason::completed : StopReason::checks_failed);
  summary_["timings"] = {{"wall_s", seconds_since(t0)}};
  save();
  write_study_report(dir_, summary_);
  if (!ok)  // a failed step may pass when resumed (memory, a killed child): the command is offered whatever stopped it
    throw RunFailed{"study stopped: " + stop_reason_ + " (results so far in " + dir_ + ")",
                    "study stopped: resume with: " + resume_command(dir_)};
  if (!failed.empty())
    throw RunFailed{"study: " + std::to_string(failed.size()) + " check(s) failed, first: " + failed[0].get<std::string>() + " (see " +
                    dir_ + "/index.md)"};
  if (!o_.common.quiet)
    std::fprintf(stderr, "study: done in %.1f s -> %s/index.md\n", summary_["timings"]["wall_s"].get<double>(), dir_.c_str());
  return 0;
}

// Runs independent steps side by side; false when the study cannot go on.
bool Study::run_steps(const std::vector<Step>& steps) {
  if (steps.empty()) return true;
  if (interrupted()) return stop(to_string(StopReason::interrupted));
  // The steps' progress on the study's line, or as lines in a log (step_progress.hpp).
  StepProgressRelay relay(progress_style(o_.common.quiet));
  std::vector<ChildTask> tasks;
  std::vector<size_t> todo;  // steps[todo[k]] is tasks[k]
  std::vector<int> codes(steps.size(), 0);
  for (size_t i = 0; i < steps.size(); ++i) {
    const Step& s = steps[i];
    const std::string folder = dir_ + "/" + s.folder;
    // Resuming: a step the stopped study saw end, with its finished result, is kept as it is.
    if (const auto done = previous_.find(s.folder); done != previous_.end() && step_done(dir_, s, done->second)) {
      codes[i] = done->second["exit_code"].get<int>();
      summary_["steps"].push_back(done->second);
      summary_["resumed_steps"] = summary_["resumed_steps"].get<int>() + 1;
      if (!o_.common.quiet) std::fprintf(stderr, "study:   %-26s done before, kept\n", s.folder.c_str());
      continue;
    }
    // Anything a stopped run left in an unfinished step's folder goes (no live process owns
    // it: steps_to_resume checked), so that the step starts as in a fresh study.
    if (!o_.resume.empty()) std::filesystem::remove_all(folder);
    std::vector<std::string> args = s.args;
    for (const std::string& set : o_.common.sets) args.insert(args.end(), {"--set", set});
    args.insert(args.end(), {"-q", "-o", folder});
    if (relay.enabled()) {
      args.insert(args.end(), {"--progress-file", folder + "/progress.txt"});
      relay.watch(s.folder, folder + "/progress.txt");
    }
    ensure_directory(folder);
    tasks.push_back(hbtrack_task(args, folder + "/log.txt"));
    todo.push_back(i);
  }
  if (!o_.common.quiet && !todo.empty()) {
    std::string names;
    for (const size_t i : todo) names += (names.empty() ? "" : ", ") + steps[i].folder;
    std::fprintf(stderr, "study: stage %d of %d, %s: running %s\n", stage_ + 1, int{kStages}, kStageNames[stage_], names.c_str());
  }
  if (!o_.resume.empty()) save();
  size_t ended = 0;
  const auto stage_start = std::chrono::steady_clock::now();
  const std::vector<int> ran = runner_.run(tasks, [&](size_t k, int code, double seconds) {
    const Step& s = steps[todo[k]];
    ++ended;
    relay.forget(s.folder);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_start).count();
    if (!o_.common.quiet) relay.say(step_end_line(s.folder, code, seconds, ended, todo.size(), elapsed));
    json record = {{"folder", s.folder}, {"exit_code", code}, {"wall_s", seconds}};
    if (code == 2 && s.may_be_refused) {
      const std::string why = child_error_line(dir_ + "/" + s.folder + "/log.txt");
      record["skipped"] = why.empty() ? "refused (see " + s.folder + "/log.txt)" : why;
      if (!o_.common.quiet) relay.say("study:   " + s.folder + " skipped: " + record["skipped"].get<std::string>());
    }
    summary_["steps"].push_back(record);
    save();
  });
  for (size_t k = 0; k < todo.size(); ++k) codes[todo[k]] = ran[k];
  for (size_t i = 0; i < steps.size(); ++i) {
    if (interrupted() || codes[i] >= 128 || codes[i] == kTaskNotStarted) return stop(to_string(StopReason::interrupted));
    if (codes[i] == 0 || (codes[i] == 1 && !steps[i].must_succeed) || (codes[i] == 2 && steps[i].may_be_refused)) continue;
    return stop(steps[i].folder + " failed (exit " + std::to_string(codes[i]) + ", see " + dir_ + "/" + steps[i].folder + "/log.txt)");
  }
  return true;
}

const json& Study::step_record(const std::string& folder) const {
  static const json none = json::object();
  const json& steps = summary_["steps"];
  for (auto it = steps.rbegin(); it != steps.rend(); ++it)
    if (it->value("folder", "") == folder) return *it;
  return none;
}

bool Study::stop(const std::string& reason) {
  stop_reason_ = reason;
  return false;
}

bool Study::nominal() {
  stage_ = kNominal;
  if (!run_steps({{"nfrc", {"frc", o_.common.case_path}, true}})) return false;
  const json s = read_summary(dir_ + "/nfrc");
  for (size_t row : limit_point_rows(s["special_points"])) limit_points_.push_back(s["special_points"][row]);  // LP1 lowest omega
  summary_["nfrc"] = {{"points", s["points"]},
                      {"special_points", s["special_points"]},
                      {"limit_points", limit_points_.size()},
                      {"stop_reason", s.value("stop_reason", "")},
                      {"wall_s", s["timings"]["wall_s"]}};
  // The contacts' loop gain, and the NFRC's warnings, which would otherwise stay in its log.
  if (s.contains("friction_loop_gain")) summary_["nfrc"]["friction_loop_gain"] = s["friction_loop_gain"];
  summary_["nfrc"]["warnings"] = s.value("warnings", json::array());
  if (!o_.common.quiet)
    for (const auto& w : summary_["nfrc"]["warnings"]) std::fprintf(stderr, "study: warning: nfrc: %s\n", w.get<std::string>().c_str());
  return true;
}

// Beside the NFRC, as [study] asks: the backbones and the tori side by side, then the branch of
// each BP and PD in turn, a point that an earlier switched branch passes through not switched again.
bool Study::branches() {
  stage_ = kBranches;
  const std::vector<BranchStep> backbones = backbone_steps(c_.study.backbones, o_.common.case_path);
  const json points = summary_["nfrc"]["special_points"];
  std::vector<TorusStep> tori;
  if (c_.study.torus.enabled)
    tori = torus_steps(o_.common.case_path, dir_ + "/nfrc", points, c_.study.torus, std::min(c_.nfrc.omega_start, c_.nfrc.omega_end),
                       std::max(c_.nfrc.omega_start, c_.nfrc.omega_end));
  std::vector<Step> steps;
  for (const BranchStep& b : backbones) steps.push_back({b.folder, b.args, false});
  // A torus the case's laws or size rule out is skipped (the verb's reason recorded), not a failure.
  for (const TorusStep& t : tori) steps.push_back({t.folder, t.args, false, true});
  if (!run_steps(steps)) return false;
  for (size_t i = 0; i < backbones.size(); ++i) summary_["backbones"].push_back(backbone_entry(dir_, backbones[i], c_.study.backbones[i]));
  if (c_.study.torus.enabled) summary_["tori"] = json::array();
  for (const TorusStep& t : tori) summary_["tori"].push_back(torus_entry(dir_, t, points, c_.outputs, step_record(t.folder)));
  if (!c_.study.switch_branches) return true;
  summary_["switched"] = json::array();
  std::vector<std::string> folders;
  for (size_t k = 0; k < points.size(); ++k) {
    const int point = static_cast<int>(k + 1);
    if (!switchable(points[k])) continue;
    if (const std::string on = switched_branch_through(dir_, folders, points[k], c_.outputs, kSameBranchOmega, kSameBranchOutput);
        !on.empty()) {
      summary_["switched"].push_back(
          {{"point", point}, {"type", points[k]["type"]}, {"omega", points[k]["omega"]}, {"on_the_branch_of", on}});
      continue;
    }
    const BranchStep s = switch_step(o_.common.case_path, dir_ + "/nfrc", points[k], point);
    if (!run_steps({{s.folder, s.args, false}})) return false;
    folders.push_back(s.folder);
    summary_["switched"].push_back(switch_entry(dir_, s.folder, points[k], point));
  }
  return true;
}

// Figures are a convenience: a missing matplotlib costs the pictures, not the study.
void Study::figures() {
  stage_ = kFigures;
  if (!o_.common.quiet) std::fprintf(stderr, "study: stage %d of %d, %s: drawing\n", stage_ + 1, int{kStages}, kStageNames[stage_]);
  summary_["figures"] = draw_study_figures(dir_, o_.units, o_.common.quiet);
}

namespace {

int run_study(const StudyOptions& options) {
  // Under mpirun the other ranks only run the steps rank 0 hands them.
  StudyOptions o = options;
  if (!o.resume.empty()) {
    if (!o.common.out_dir.empty() && o.common.out_dir != o.resume)
      throw CaseError("--resume: continues in its own folder, give no other -o");
    o.common.out_dir = o.resume;
  }
  if (o.common.out_dir.empty()) throw CaseError("--output is required (or --resume DIR)");
  const std::unique_ptr<TaskRunner> runner = start_task_runner(o.jobs);
  if (!runner) return 0;
  const CaseDefinition c = load_case(o.common.case_path, o.common.sets);
  if (c.study.track.empty() && c.study.backbones.empty() && !c.study.switch_branches && !c.study.torus.enabled)
    throw CaseError(o.common.case_path +
                    ": study.track: missing (the parameters to track, or a backbone, switch = true or torus = true: nothing to study; "
                    "see docs/study.md)");
  // Checked before the nominal NFRC: frc alone changes H along a branch; the tracking, isolas
  // and tori the study runs next would refuse the case after minutes of work.
  if (c.harmonic_balance.adaptive.enabled())
    throw CaseError(o.common.case_path +
                    ": harmonic_balance.adaptive: a study holds one H (its tracking, isolas and tori take no adaptive harmonics); "
                    "leave adaptive out, or --set harmonic_balance.adaptive.max=0");
  for (const std::string& name : o.only) {
    const bool known = std::any_of(c.study.track.begin(), c.study.track.end(), [&](const StudyTrack& t) { return t.parameter == name; });
    if (!known) throw CaseError("--only: '" + name + "' is not tracked in the case's [study] section");
  }
  Study study(o, c, *runner);
  return study.run();
}

void add_study_verb(CLI::App& app, VerbList& verbs) {
  static StudyOptions options;
  CLI::App* s =
      app.add_subcommand("study", "the whole analysis of a case: NFRC, tracking of every limit point, isolas, validation, figures");
  add_common_options(s, options.common);
  s->add_option("--only", options.only, "track only this parameter of [study] (repeatable)")->type_name("NAME");
  s->add_option("--units", options.units, "the model's length unit, for the figures' labels (e.g. m)")->type_name("UNIT");
  add_jobs_option(s, options.jobs, "independent steps");
  s->get_option("--output")->required(false);  // --resume DIR names the folder instead
  s->add_option("--resume", options.resume,
                "go on with the stopped study in this folder, keeping its finished steps (same case, --set, --only)")
      ->type_name("DIR");
  verbs.push_back({s, [] { return run_study(options); }});
}

const VerbRegistrar study_registrar(add_study_verb);

}  // namespace

}  // namespace hbtrack::cli
