// `hbtrack sweep`: the same analysis over many parameter values. Each task is what a user would
// type (`hbtrack frc CASE --set NAME=VALUE ... -o DIR/tasks/NNNN`, and with --track one
// `hbtrack track` per limit point of it) run as a child process by the task runner, on this
// machine (--jobs) or on MPI ranks (mpirun). DIR/sweep.json holds the definition: a rerun with
// the same one skips every task whose folder holds a finished result, so a killed sweep loses at
// most the tasks that were running; a rerun with another definition is refused.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include "cli_common.hpp"
#include "folder_lock.hpp"
#include "hbtrack/io/json_file.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "hbtrack/util/stop_reason.hpp"
#include "result_folder.hpp"
#include "resume_command.hpp"
#include "sweep_definition.hpp"
#include "sweep_table.hpp"
#include "task_runner.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct SweepOptions {
  CommonOptions common;
  std::vector<std::string> params, values;
  std::string samples, track;
  int jobs = 0;
};

// DIR may be new, empty, or hold this same sweep; anything else is refused before it is touched.
void claim_folder(const std::string& dir, const json& definition) {
  namespace fs = std::filesystem;
  const std::string saved_path = dir + "/sweep.json";
  if (fs::exists(saved_path)) {
    lock_result_folder(dir);
    json saved;
    try {
      saved = read_json_file(saved_path, "a sweep definition");
    } catch (const CaseError& e) {
      throw CaseError("-o: " + std::string(e.what()) + " (delete " + dir + " to start over)");
    }
    for (const auto& [key, value] : definition.items())
      if (!saved.contains(key) || saved[key] != value)
        throw CaseError("-o: " + dir + " holds a sweep with other settings (" + key +
                        " differs from its sweep.json); use another folder or delete it");
    return;
  }
  if (fs::exists(dir) && (!fs::is_directory(dir) || !fs::is_empty(dir)))
    throw CaseError("-o: " + dir + " is not empty and holds no sweep.json (not a sweep folder)");
  ensure_directory(dir);
  lock_result_folder(dir);
  write_json_atomically(saved_path, definition);
}

class Sweep {
 public:
  Sweep(const SweepOptions& o, const CaseDefinition& c, SweepGrid grid, std::optional<SweepTracking> tracking, TaskRunner& runner)
      : o_(o),
        dir_(o.common.out_dir),
        grid_(std::move(grid)),
        tracking_(std::move(tracking)),
        runner_(runner),
        unfinished_(grid_.tasks.size(), Unfinished::kPending) {
    for (const OutputDof& out : c.outputs) outputs_.push_back(out.name);
  }

  int run() {
    const auto t0 = Clock::now();
    summary_ = {{"verb", "sweep"},
                {"case", o_.common.case_path},
                {"tasks", grid_.tasks.size()},
                {"runner", runner_.description()},
                {"stop_reason", to_string(StopReason::running)},
                {"computed", 0},
                {"skipped", 0},
                {"task_wall_s", 0.0}};
    save();
    if (!o_.common.quiet)
      std::fprintf(stderr, "sweep: %zu tasks on %s -> %s\n", grid_.tasks.size(), runner_.description().c_str(), dir_.c_str());
    run_phase("nfrc", nfrc_tasks());
    if (tracking_ && !interrupted()) run_phase("track", tracking_tasks());
    write_sweep_table(dir_, grid_, outputs_, tracking_, unfinished_);
    size_t missing = 0;
    for (size_t i = 0; i < grid_.tasks.size(); ++i)
      if (!task_finished(i)) ++missing;
    summary_["stop_reason"] = to_string(interrupted() ? StopReason::interrupted
                                        : missing > 0 ? StopReason::tasks_failed
                                                      : StopReason::completed);
    summary_["unfinished"] = missing;
    summary_["timings"] = {{"wall_s", seconds_since(t0)}};
    save();
    if (interrupted())
      throw RunFailed{"sweep interrupted: " + std::to_string(grid_.tasks.size() - missing) + " of " + std::to_string(grid_.tasks.size()) +
                          " tasks finished",
                      // A sweep resumes by running again: the finished tasks are skipped.
                      resume_advice(to_string(StopReason::interrupted), typed_command())};
    if (missing > 0)
      throw RunFailed{std::to_string(missing) + " of " + std::to_string(grid_.tasks.size()) + " tasks left no result (see their log.txt; " +
                      dir_ + "/sweep.csv)"};
    if (!o_.common.quiet)
      std::fprintf(stderr, "sweep: done in %s -> %s/sweep.csv\n", duration_text(seconds_since(t0)).c_str(), dir_.c_str());
    return 0;
  }

 private:
  struct Task {
    size_t sweep_index;
    std::string folder;
    std::vector<std::string> args;
  };

  std::string folder(size_t i) const { return task_folder(dir_, i, grid_.tasks.size()); }
  std::string nfrc_folder(size_t i) const { return folder(i) + (tracking_ ? "/nfrc" : ""); }
  std::vector<std::string> with_sets(std::vector<std::string> args, size_t i) const {
    for (const std::string& s : o_.common.sets) args.insert(args.end(), {"--set", s});
    for (size_t j = 0; j < grid_.names.size(); ++j) args.insert(args.end(), {"--set", grid_.names[j] + "=" + grid_.tasks[i][j]});
    return args;
  }

  std::vector<Task> nfrc_tasks() const {
    std::vector<Task> tasks;
    for (size_t i = 0; i < grid_.tasks.size(); ++i) tasks.push_back({i, nfrc_folder(i), with_sets({"frc", o_.common.case_path}, i)});
    return tasks;
  }

  // Every limit point of every finished NFRC, followed in the tracked parameter.
  std::vector<Task> tracking_tasks() const {
    std::vector<Task> tasks;
    const std::string range = number_text(tracking_->min, 17) + ":" + number_text(tracking_->max, 17);
    for (size_t i = 0; i < grid_.tasks.size(); ++i) {
      if (!finished_result(nfrc_folder(i))) continue;
      const size_t count = limit_point_rows(read_summary(nfrc_folder(i)).value("special_points", json::array())).size();
      for (size_t lp = 1; lp <= count; ++lp) {  // --lp K: the K-th in increasing omega
        tasks.push_back({i, folder(i) + "/track_lp" + std::to_string(lp),
                         with_sets({"track", o_.common.case_path, "--from", nfrc_folder(i), "--lp", std::to_string(lp), "--param",
                                    tracking_->parameter, "--range", range},
                                   i)});
      }
    }
    return tasks;
  }

  bool task_finished(size_t i) const {
    if (!finished_result(nfrc_folder(i))) return false;
    if (!tracking_) return true;
    int lp = 0;
    for (const auto& sp : read_summary(nfrc_folder(i)).value("special_points", json::array()))
      if (runs::special_point_is(sp, SpecialPointType::limit_point) && !finished_result(folder(i) + "/track_lp" + std::to_string(++lp)))
        return false;
    return true;
  }

  // Runs the tasks of one phase that have no finished result yet, with progress and an estimate
  // of the time left from this run's throughput.
  void run_phase(const std::string& phase, const std::vector<Task>& all) {
    std::vector<const Task*> todo;
    std::vector<ChildTask> children;
    size_t owned_elsewhere = 0;
    for (const Task& t : all) {
      if (finished_result(t.folder)) continue;
      // Still computed by a run this sweep did not start (the orphan of a killed sweep): a
      // second writer would mix the two runs' rows, so it is left alone and stays unfinished.
      if (const long owner = result_folder_owner(t.folder); owner != 0) {
        ++owned_elsewhere;  // said even with -q: it is why the sweep ends unfinished
        std::fprintf(stderr, "sweep: %s: %s is still being computed by pid %ld, not started again\n", phase.c_str(),
                     t.folder.substr(dir_.size() + 1).c_str(), owner);
        continue;
      }
      ensure_directory(t.folder);
      std::vector<std::string> args = t.args;
      args.insert(args.end(), {"-q", "-o", t.folder});
      children.push_back(hbtrack_task(args, t.folder + "/log.txt"));
      todo.push_back(&t);
    }
    const size_t skipped = all.size() - todo.size() - owned_elsewhere;
    summary_["skipped"] = summary_["skipped"].get<size_t>() + skipped;
    if (!o_.common.quiet && skipped > 0)
      std::fprintf(stderr, "sweep: %s: %zu of %zu already finished in %s, not recomputed\n", phase.c_str(), skipped, all.size(),
                   dir_.c_str());
    const auto t0 = Clock::now();
    size_t done = 0;
    runner_.run(children, [&](size_t k, int code, double seconds) {
      const Task& t = *todo[k];
      ++done;
      const bool finished = finished_result(t.folder);
      if (!finished && !interrupted()) unfinished_[t.sweep_index] = Unfinished::kError;
      summary_["computed"] = summary_["computed"].get<size_t>() + 1;
      summary_["task_wall_s"] = summary_["task_wall_s"].get<double>() + seconds;
      save();
      if (o_.common.quiet) return;
      const std::string status =
          finished ? read_summary(t.folder).value("stop_reason", "") : "exit " + std::to_string(code) + ", see log.txt";
      const double left = seconds_since(t0) / static_cast<double>(done) * static_cast<double>(todo.size() - done);
      std::fprintf(stderr, "sweep: %s %s: %s, %.1f s; %zu/%zu done, ~%s left\n", phase.c_str(), t.folder.substr(dir_.size() + 1).c_str(),
                   status.c_str(), seconds, skipped + done, all.size(), duration_text(left).c_str());
    });
  }

  void save() const { write_json_atomically(dir_ + "/summary.json", summary_); }

  const SweepOptions& o_;
  const std::string dir_;
  const SweepGrid grid_;
  const std::optional<SweepTracking> tracking_;
  TaskRunner& runner_;
  std::vector<std::string> outputs_;
  std::vector<Unfinished> unfinished_;
  json summary_;
};

int run_sweep(const SweepOptions& o) {
  // Under mpirun the other ranks only run the tasks rank 0 hands them.
  const std::unique_ptr<TaskRunner> runner = start_task_runner(o.jobs);
  if (!runner) return 0;
  const CaseDefinition c = load_case(o.common.case_path, o.common.sets);
  if (!o.samples.empty() && !o.params.empty()) throw CaseError("--samples: give either --samples or --param/--values, not both");
  const SweepGrid grid = o.samples.empty() ? cartesian_grid(o.params, o.values) : read_samples(o.samples);
  check_grid_names(grid, c, o.common.sets, o.samples.empty() ? "--param:" : o.samples + ":1: column");
  std::optional<SweepTracking> tracking;
  if (!o.track.empty()) tracking = parse_tracking(o.track, grid, c);
  claim_folder(o.common.out_dir, sweep_definition_json(o.common.case_path, o.common.sets, grid, tracking));
  Sweep sweep(o, c, grid, tracking, *runner);
  return sweep.run();
}

void add_sweep_verb(CLI::App& app, VerbList& verbs) {
  static SweepOptions options;
  CLI::App* s =
      app.add_subcommand("sweep", "NFRCs (or limit-point tracking) over a grid or table of parameter values, on threads or MPI ranks");
  add_common_options(s, options.common);
  s->add_option("--param", options.params, "a named parameter to vary (repeatable, each with its --values)")->type_name("NAME");
  s->add_option("--values", options.values, "its values: A,B,C or LO:HI:count=N (N evenly spaced values, ends included; not a step)")
      ->type_name("LIST");
  s->add_option("--samples", options.samples, "a CSV table instead: a header of parameter names, one task per row")->type_name("FILE");
  s->add_option("--track", options.track, "follow every limit point of each NFRC in PARAM over LO:HI (default: the case's [study] range)")
      ->type_name("PARAM[:LO:HI]");
  add_jobs_option(s, options.jobs, "tasks");
  verbs.push_back({s, [] { return run_sweep(options); }});
}

const VerbRegistrar sweep_registrar(add_sweep_verb);

}  // namespace

}  // namespace hbtrack::cli
