// `hbtrack study`: the paper's whole analysis of one case, as the verbs a user would run by hand,
// each a child process writing its own result folder under DIR (independent ones side by side, on
// this machine or on MPI ranks: task_runner.hpp):
//   nfrc/                 the nominal NFRC with stability
//   backbone_modeK/       with [study] backbone: the nonlinear mode K (study_branches.hpp)
//   switch_bpK/, _pdK/    with [study] switch: the branch born at the NFRC's special point K
//   track_P_lpK/          limit point K followed in parameter P (the case's [study] section)
//   validate_P_J/         an NFRC at a parameter value next to each extremum of the P curves
//   crossings_P_J/        the limit points of the tracking curves at that value, located
//   isolas_P_J/           the branches through the crossings no validation NFRC holds
//   simulate/             time integration from the stable resonance point of the NFRC
//   simulate_isola/       time integration from the stable isola point of largest output
//   converged/            with [study] convergence: the NFRC and tracking curves at more H, N
//   figures/, index.md    the figures and a page with the numbers (study_report.cpp)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "cli_common.hpp"
#include "folder_lock.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "hbtrack/util/stop_reason.hpp"
#include "result_folder.hpp"
#include "resume_command.hpp"
#include "step_progress.hpp"
#include "study_branches.hpp"
#include "study_comparisons.hpp"
#include "study_curves.hpp"
#include "study_figures_step.hpp"
#include "study_checks.hpp"
#include "study_report.hpp"
#include "study_plan.hpp"
#include "study_resume.hpp"
#include "task_runner.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

struct StudyOptions {
  CommonOptions common;
  std::vector<std::string> only;  // restrict the tracked parameters
  int jobs = 0;                   // steps side by side; 0: one per core
  std::string units;              // the model's length unit, for the figures' labels
  std::string resume;             // a stopped study's folder to go on in (study_resume.hpp)
};

// The same extremum reached again (a curve that passes it twice, or the other LP's curve).
bool already_listed(const json& extrema, const TrackingCurve::Extremum& e) {
  for (const auto& x : extrema)
    if (x["type"] == e.type && std::abs(x["value"].get<double>() - e.value) <= 1e-9 * std::abs(e.value) &&
        std::abs(x["omega"].get<double>() - e.omega) <= 1e-9 * std::abs(e.omega))
      return true;
  return false;
}

class Study {
 public:
  Study(const StudyOptions& o, const CaseDefinition& c, TaskRunner& runner) : o_(o), c_(c), dir_(o.common.out_dir), runner_(runner) {
    for (const StudyTrack& t : c_.study.track)
      if (o_.only.empty() || std::find(o_.only.begin(), o_.only.end(), t.parameter) != o_.only.end()) tracked_.push_back(t);
  }

  int run() {
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
    const bool ok = nominal() && branches() && tracking() && validation_and_simulation() && added_families() && isolas() &&
                    isola_simulation() && convergence();
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

 private:
  // Runs independent steps side by side; false when the study cannot go on.
  bool run_steps(const std::vector<Step>& steps) {
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
      if (const auto done = previous_.find(s.folder); done != previous_.end() && step_done(dir_, s.folder, done->second, s.must_succeed)) {
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
    const std::vector<int> ran = runner_.run(tasks, [&](size_t k, int code, double seconds) {
      const Step& s = steps[todo[k]];
      ++ended;
      relay.forget(s.folder);
      if (!o_.common.quiet) {
        char line[256];
        std::snprintf(line, sizeof line, "study:   %-26s exit %d, %.1f s (step %zu of %zu)", s.folder.c_str(), code, seconds, ended,
                      todo.size());
        relay.say(line);
      }
      summary_["steps"].push_back({{"folder", s.folder}, {"exit_code", code}, {"wall_s", seconds}});
      save();
    });
    for (size_t k = 0; k < todo.size(); ++k) codes[todo[k]] = ran[k];
    for (size_t i = 0; i < steps.size(); ++i) {
      if (interrupted() || codes[i] >= 128 || codes[i] == kTaskNotStarted) return stop(to_string(StopReason::interrupted));
      if (codes[i] == 0 || (codes[i] == 1 && !steps[i].must_succeed)) continue;
      return stop(steps[i].folder + " failed (exit " + std::to_string(codes[i]) + ", see " + dir_ + "/" + steps[i].folder + "/log.txt)");
    }
    return true;
  }
  bool stop(const std::string& reason) {
    stop_reason_ = reason;
    return false;
  }
  void save() const { write_json_atomically(dir_ + "/summary.json", summary_); }
  std::string first_output() const { return c_.outputs.empty() ? "" : c_.outputs.front().name; }
  double case_value(const std::string& name) const { return c_.parameters.value(c_.parameters.find(name)); }

  bool nominal() {
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

  // Beside the NFRC, as [study] asks: the backbones side by side, then the branch of each BP and
  // PD in turn, a point that an earlier switched branch passes through not switched again.
  bool branches() {
    stage_ = kBranches;
    const std::vector<BranchStep> backbones = backbone_steps(c_.study.backbones, o_.common.case_path);
    std::vector<Step> steps;
    for (const BranchStep& b : backbones) steps.push_back({b.folder, b.args, false});
    if (!run_steps(steps)) return false;
    for (size_t i = 0; i < backbones.size(); ++i)
      summary_["backbones"].push_back(backbone_entry(dir_, backbones[i], c_.study.backbones[i]));
    if (!c_.study.switch_branches) return true;
    summary_["switched"] = json::array();
    std::vector<std::string> folders;
    const json points = summary_["nfrc"]["special_points"];
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

  // Round k follows the k-th limit point in every parameter at once; a limit point that already
  // lies on an earlier curve of the same parameter (the two folds of one cusp) is not tracked again.
  bool tracking() {
    stage_ = kTracking;
    summary_["tracking"] = json::array();
    const std::string out = first_output();
    for (const StudyTrack& t : tracked_)
      entries_[t.parameter] = {{"parameter", t.parameter},
                               {"range", {t.min, t.max}},
                               {"curves", json::array()},
                               {"extrema", json::array()},
                               {"validations", json::array()}};
    for (size_t k = 0; k < limit_points_.size(); ++k) {
      const json& lp = limit_points_[k];
      const double omega = lp.value("omega", 0.0), output = out.empty() ? 0.0 : lp.value("max_" + out, 0.0);
      std::vector<Step> round;
      std::vector<const StudyTrack*> which;
      for (const StudyTrack& t : tracked_) {
        // Interpolated between tracking points: a coarser test than kSameLimitPoint.
        if (lies_on_a_curve(curves_[t.parameter], case_value(t.parameter), omega, output, 1e-3)) {
          entries_[t.parameter]["curves"].push_back({{"lp", k + 1}, {"omega", omega}, {"same_curve_as_earlier_lp", true}});
          continue;
        }
        const std::string range = number_text(t.min) + ":" + number_text(t.max);
        round.push_back({"track_" + t.parameter + "_lp" + std::to_string(k + 1),
                         {"track", o_.common.case_path, "--from", dir_ + "/nfrc", "--lp", std::to_string(k + 1), "--param", t.parameter,
                          "--range", range, "--set", "continuation.max_points=" + std::to_string(c_.study.max_points)},
                         false});
        which.push_back(&t);
      }
      if (!run_steps(round)) return false;
      for (size_t i = 0; i < round.size(); ++i) add_curve(*which[i], k + 1, omega, round[i].folder);
    }
    return true;
  }

  void add_curve(const StudyTrack& t, size_t lp, double omega, const std::string& folder) {
    const std::string out = first_output();
    const json s = read_summary(dir_ + "/" + folder);
    curves_[t.parameter].push_back(read_tracking_curve_folder(dir_ + "/" + folder, t.parameter, out));
    json& entry = entries_[t.parameter];
    entry["curves"].push_back({{"lp", lp},
                               {"omega", omega},
                               {"folder", folder},
                               {"points", s.value("points", 0)},
                               {"stop_reason", s.value("stop_reason", "")},
                               {"closed", s.value("closed", false)},
                               {"wall_s", s["timings"].value("wall_s", 0.0)}});
    for (const auto& e : curves_[t.parameter].back().extrema)
      if (!already_listed(entry["extrema"], e))
        entry["extrema"].push_back(
            {{"type", e.type}, {"value", e.value}, {"omega", e.omega}, {"max_" + out, e.first_output}, {"curve", folder}});
  }

  // NFRCs from the linear solution next to every extremum (or at both ends of a range without
  // one), the tracking curves' limit points located at the same values, and the time
  // integration: all independent of each other.
  bool validation_and_simulation() {
    stage_ = kValidation;
    std::vector<Step> frcs, crossings;
    for (const StudyTrack& t : tracked_) {
      if (curves_[t.parameter].empty()) continue;
      std::vector<double> probes = probe_values(curves_[t.parameter], t.min, t.max, kProbeOffset);
      // The case's own values (a paper's validation NFRCs), unless one is already there.
      for (double v : t.validate)
        if (std::none_of(probes.begin(), probes.end(), [&](double p) { return std::abs(p - v) <= 1e-12 * std::abs(v); }))
          probes.push_back(v);
      std::sort(probes.begin(), probes.end());
      for (size_t j = 0; j < probes.size(); ++j) {
        const std::string tag = t.parameter + "_" + std::to_string(j + 1), at = number_text(probes[j]);
        probes_.push_back({&t, probes[j], tag});
        frcs.push_back(
            {"validate_" + tag, {"frc", o_.common.case_path, "--set", t.parameter + "=" + at, "--set", "stability.method=none"}, false});
        Step locate{"crossings_" + tag, {"isolas", o_.common.case_path, "--at", at, "--locate-only"}, true};
        for (const TrackingCurve& c : curves_[t.parameter]) locate.args.insert(locate.args.end(), {"--from", c.folder});
        crossings.push_back(locate);
      }
    }
    const long point = simulation_point();
    if (point >= 0) {
      const int periods = c_.study.simulate_periods;
      frcs.push_back({"simulate",
                      {"simulate", o_.common.case_path, "--from", dir_ + "/nfrc", "--point", std::to_string(point), "--max-periods",
                       std::to_string(periods), "--record-periods", std::to_string(std::min(4, periods))},
                      false});
    }
    if (!run_steps(frcs) || !run_steps(crossings) || !continue_validations_beyond_the_range()) return false;
    for (const Probe& p : probes_) compare(p);
    if (point >= 0) compare_simulation(point);
    return true;
  }

  struct Probe {
    const StudyTrack* track;
    double value;
    std::string tag;
  };

  // A validation NFRC that left through the start of its range (its branch turned back past
  // omega_start) is computed again over a range widened beyond the start by one range width (at
  // most to 5 % of it): the branch then runs through its turning point there and on, and every
  // limit point it meets is compared.
  bool continue_validations_beyond_the_range() {
    const double start = c_.nfrc.omega_start, end = c_.nfrc.omega_end;
    const double beyond = start < end ? std::max(start - (end - start), 0.05 * start) : start + (start - end);
    std::vector<Step> steps;
    for (const Probe& p : probes_)
      if (read_summary(dir_ + "/validate_" + p.tag).value("stop_reason", "") == to_string(StopReason::left_range))
        steps.push_back({"validate_" + p.tag + "_beyond",
                         {"frc", o_.common.case_path, "--set", p.track->parameter + "=" + number_text(p.value), "--set",
                          "continuation.omega_start=" + number_text(beyond), "--set", "stability.method=none"},
                         false});
    return run_steps(steps);
  }

  void compare(const Probe& p) {
    json validation = read_summary(dir_ + "/validate_" + p.tag);
    json beyond;
    std::string lp_folder = "validate_" + p.tag;
    if (const std::string folder = "validate_" + p.tag + "_beyond"; std::filesystem::exists(dir_ + "/" + folder + "/summary.json")) {
      lp_folder = folder;
      // The widened run holds the whole branch: its limit points replace the validation's.
      const json s = read_summary(dir_ + "/" + folder);
      validation["special_points"] = s.value("special_points", json::array());
      beyond = {
          {"folder", folder}, {"stop_reason", s.value("stop_reason", "")}, {"omega_start", s["options"]["continuation"]["omega_start"]}};
    }
    const std::string crossings = crossings_folder_.count(p.tag) ? crossings_folder_[p.tag] : "crossings_" + p.tag;
    json entry = validation_against_crossings(validation, read_summary(dir_ + "/" + crossings)["crossings"], first_output());
    entry["value"] = p.value;
    entry["folder"] = "validate_" + p.tag;
    entry["limit_points_folder"] = lp_folder;
    entry["stop_reason"] = validation.value("stop_reason", "");
    if (!beyond.is_null()) entry["beyond"] = beyond;
    entries_[p.track->parameter]["validations"].push_back(entry);
  }

  // A validation NFRC's limit point on no tracking curve belongs to a family no limit point of the
  // nominal NFRC leads to: it is tracked from that NFRC (`track_P_addedK/`, at most
  // study.max_added_curves per parameter, one per parameter at a time so that a second limit
  // point of the same family is not tracked twice), then the crossings at every validation value
  // of P are located again with every curve (`crossings_P_J_all/`) and the NFRCs compared again.
  bool added_families() {
    std::map<std::string, int> added;
    while (true) {
      std::vector<Step> round;
      std::vector<const StudyTrack*> which;
      std::vector<OffCurveLimitPoint> starts;
      for (const StudyTrack& t : tracked_) {
        if (added[t.parameter] >= c_.study.max_added_curves) continue;
        const auto lp = first_limit_point_off_the_curves(dir_, entries_[t.parameter]["validations"], tried_);
        if (!lp) continue;
        tried_.insert(lp->folder + "#" + std::to_string(lp->index));
        const int k = ++added[t.parameter];
        round.push_back({"track_" + t.parameter + "_added" + std::to_string(k),
                         {"track", o_.common.case_path, "--from", dir_ + "/" + lp->folder, "--lp", std::to_string(lp->index), "--param",
                          t.parameter, "--range", number_text(t.min) + ":" + number_text(t.max), "--set",
                          "continuation.max_points=" + std::to_string(c_.study.max_points)},
                         false});
        which.push_back(&t);
        starts.push_back(*lp);
      }
      if (round.empty()) return true;
      stage_ = kTracking;
      if (!run_steps(round)) return false;
      std::vector<Step> crossings;
      for (size_t i = 0; i < round.size(); ++i) {
        add_curve(*which[i], 0, starts[i].omega, round[i].folder);
        entries_[which[i]->parameter]["curves"].back()["from"] = starts[i].folder + " LP" + std::to_string(starts[i].index);
      }
      for (const Probe& p : probes_) {
        if (std::find(which.begin(), which.end(), p.track) == which.end()) continue;
        Step locate{"crossings_" + p.tag + "_all" + std::to_string(added[p.track->parameter]),
                    {"isolas", o_.common.case_path, "--at", number_text(p.value), "--locate-only"},
                    true};
        for (const TrackingCurve& c : curves_[p.track->parameter]) locate.args.insert(locate.args.end(), {"--from", c.folder});
        crossings_folder_[p.tag] = locate.folder;
        crossings.push_back(locate);
      }
      if (!run_steps(crossings)) return false;
      for (const StudyTrack* t : which) entries_[t->parameter]["validations"] = json::array();
      for (const Probe& p : probes_)
        if (std::find(which.begin(), which.end(), p.track) != which.end()) compare(p);
    }
  }

  // Limit points of the tracking curves that no NFRC from the linear solution passes announce
  // isolated branches: `isolas` follows each until it closes.
  bool isolas() {
    stage_ = kIsolas;
    std::vector<Step> steps;
    std::vector<json*> where;
    for (const Probe& p : probes_) {
      json& validations = entries_[p.track->parameter]["validations"];
      for (auto& v : validations) {
        if (v["folder"] != "validate_" + p.tag || v["crossings_not_on_the_nfrc"].get<int>() == 0) continue;
        Step s{"isolas_" + p.tag, {"isolas", o_.common.case_path, "--at", number_text(p.value)}, false};
        for (const TrackingCurve& c : curves_[p.track->parameter]) s.args.insert(s.args.end(), {"--from", c.folder});
        steps.push_back(s);
        where.push_back(&v);
      }
    }
    if (!run_steps(steps)) return false;
    for (size_t i = 0; i < steps.size(); ++i) {
      json& v = *where[i];
      const json s = read_summary(dir_ + "/" + steps[i].folder);
      v["isolas_folder"] = steps[i].folder;
      v["isolas"] = s.value("isolas", 0);
      v["isola_branches"] = json::array();
      for (const auto& x : s.value("crossings", json::array()))
        if (x.value("status", "") == "isola")
          v["isola_branches"].push_back({{"folder", steps[i].folder + "/" + x.value("folder", "")},
                                         {"omega_range", x["omega_range"]},
                                         {"points", x["points"]},
                                         {"unstable_points", x["unstable_points"]},
                                         {"special_points", x["special_points"]}});
    }
    return true;
  }

  long simulation_point() const {
    if (c_.study.simulate_periods <= 0 || c_.outputs.empty()) return -1;
    return resonance_simulation_point(dir_ + "/nfrc", limit_points_, first_output());
  }

  void compare_simulation(long point) {
    summary_["simulation"] = compare_with_simulation(dir_ + "/nfrc", point, read_summary(dir_ + "/simulate"), c_.outputs);
    save();
  }

  // The paper's Fig. 12: a stable point of an isolated branch, integrated in time.
  bool isola_simulation() {
    stage_ = kIsolaSimulation;
    if (c_.study.simulate_periods <= 0 || c_.outputs.empty()) return true;
    json tracking = json::array();
    for (const StudyTrack& t : tracked_) tracking.push_back(entries_[t.parameter]);
    const auto at = stable_isola_point(dir_, tracking, first_output());
    if (!at) return true;
    const int periods = c_.study.simulate_periods;
    // `simulate --from` takes the isola's parameter values from its folder's summary.
    const std::string from = dir_ + "/" + at->folder;
    std::vector<std::string> args{"simulate",         o_.common.case_path,
                                  "--from",           from,
                                  "--point",          std::to_string(at->point),
                                  "--max-periods",    std::to_string(periods),
                                  "--record-periods", std::to_string(std::min(4, periods))};
    if (!run_steps({{"simulate_isola", args, false}})) return false;
    summary_["isola_simulation"] = compare_with_simulation(from, at->point, read_summary(dir_ + "/simulate_isola"), c_.outputs);
    summary_["isola_simulation"]["folder"] = at->folder;
    save();
    return true;
  }

  // Every event recomputed with more harmonics and samples: the nominal NFRC, then each tracking
  // curve from the refined NFRC's limit point nearest the original's.
  bool convergence() {
    stage_ = kConvergence;
    const int h = c_.study.convergence_harmonics, n = c_.study.convergence_samples;
    if (h <= 0) return true;
    const std::vector<std::string> refine{"--set", "harmonic_balance.harmonics=" + std::to_string(h), "--set",
                                          "harmonic_balance.samples=" + std::to_string(n)};
    auto with_refine = [&](std::vector<std::string> args) {
      args.insert(args.end(), refine.begin(), refine.end());
      return args;
    };
    if (!run_steps({{"converged/nfrc", with_refine({"frc", o_.common.case_path, "--set", "stability.method=none"}), false}})) return false;
    const json refined = read_summary(dir_ + "/converged/nfrc");
    json report = {{"harmonics", h},
                   {"samples", n},
                   {"limit_points", compare_limit_points(summary_["nfrc"]["special_points"], refined.value("special_points", json::array()),
                                                         first_output())},
                   {"tracking", json::array()}};
    std::vector<Step> steps;
    std::vector<const StudyTrack*> which;
    for (const StudyTrack& t : tracked_)
      for (const auto& curve : entries_[t.parameter]["curves"]) {
        if (!curve.contains("folder")) continue;
        if (curve.value("lp", 0) == 0) continue;  // an added family's: started from a validation NFRC
        const size_t lp = nearest_limit_point(refined.value("special_points", json::array()), curve.value("omega", 0.0));
        if (lp == 0) continue;
        const std::string folder = "converged/" + curve.value("folder", std::string());
        steps.push_back({folder,
                         with_refine({"track", o_.common.case_path, "--from", dir_ + "/converged/nfrc", "--lp", std::to_string(lp),
                                      "--param", t.parameter, "--range", number_text(t.min) + ":" + number_text(t.max), "--set",
                                      "continuation.max_points=" + std::to_string(c_.study.max_points)}),
                         false});
        which.push_back(&t);
      }
    if (!run_steps(steps)) return false;
    std::map<std::string, std::vector<TrackingCurve>> refined_curves;
    for (size_t i = 0; i < steps.size(); ++i)
      refined_curves[which[i]->parameter].push_back(
          read_tracking_curve_folder(dir_ + "/" + steps[i].folder, which[i]->parameter, first_output()));
    for (const StudyTrack& t : tracked_)
      report["tracking"].push_back(
          {{"parameter", t.parameter},
           {"extrema", compare_extrema(entries_[t.parameter]["extrema"], refined_curves[t.parameter], first_output())}});
    summary_["convergence"] = report;
    save();
    return true;
  }

  // Figures are a convenience: a missing matplotlib costs the pictures, not the study.
  void figures() {
    stage_ = kFigures;
    if (!o_.common.quiet) std::fprintf(stderr, "study: stage %d of %d, %s: drawing\n", stage_ + 1, int{kStages}, kStageNames[stage_]);
    summary_["figures"] = draw_study_figures(dir_, o_.units, o_.common.quiet);
  }

  const StudyOptions& o_;
  const CaseDefinition& c_;
  const std::string dir_;
  TaskRunner& runner_;
  std::vector<StudyTrack> tracked_;
  json summary_;
  json limit_points_ = json::array();
  std::map<std::string, json> entries_;  // per tracked parameter: curves, extrema, validations
  std::map<std::string, std::vector<TrackingCurve>> curves_;
  std::vector<Probe> probes_;
  std::map<std::string, std::string> crossings_folder_;  // a probe's crossings located again with added curves
  std::set<std::string> tried_;                          // "folder#K": limit points an added curve started from
  std::string stop_reason_;
  Stage stage_ = kNominal;
  std::map<std::string, json> previous_;  // resuming: the stopped study's ended steps, by folder
};

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
  if (c.study.track.empty() && c.study.backbones.empty() && !c.study.switch_branches)
    throw CaseError(
        o.common.case_path +
        ": study.track: missing (the parameters to track, or a backbone or switch = true: nothing to study; see docs/study.md)");
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
