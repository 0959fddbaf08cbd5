// The study's validation stages (study.hpp): NFRCs next to every extremum of the tracking curves
// compared with the curves' crossings, the isolated branches those announce, and the time
// integrations of a resonance point and an isola point.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "cli_common.hpp"
#include "result_folder.hpp"
#include "study.hpp"
#include "study_comparisons.hpp"
#include "study_curves.hpp"
#include "study_plan.hpp"

namespace hbtrack::cli {

using nlohmann::json;

// NFRCs from the linear solution next to every extremum (or at both ends of a range without
// one), the tracking curves' limit points located at the same values, and the time
// integration: all independent of each other.
bool Study::validation_and_simulation() {
  stage_ = kValidation;
  std::vector<Step> frcs, crossings;  // run as one batch, the time integration first
  for (const StudyTrack& t : tracked_) {
    if (curves_[t.parameter].empty()) continue;
    std::vector<double> probes = probe_values(curves_[t.parameter], t.min, t.max, kProbeOffset);
    // The case's own values (a paper's validation NFRCs), unless one is already there.
    for (double v : t.validate)
      if (std::none_of(probes.begin(), probes.end(), [&](double p) { return std::abs(p - v) <= 1e-12 * std::abs(v); })) probes.push_back(v);
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
  // The resonance's time integration: from the stable side of the fold next to the largest stable
  // response, closest first, until the full model holds the orbit (`simulate --near-lp`); from
  // that response itself when the NFRC has no stability to tell the fold's sides apart.
  const ResonanceStart start = resonance_start();
  if (start.fold > 0 || start.point >= 0) {
    const int periods = c_.study.simulate_periods;
    Step simulate{"simulate", {"simulate", o_.common.case_path, "--from", dir_ + "/nfrc"}, false};
    const std::vector<std::string> where = start.fold > 0 ? std::vector<std::string>{"--near-lp", std::to_string(start.fold)}
                                                          : std::vector<std::string>{"--point", std::to_string(start.point)};
    simulate.args.insert(simulate.args.end(), where.begin(), where.end());
    simulate.args.insert(simulate.args.end(),
                         {"--max-periods", std::to_string(periods), "--record-periods", std::to_string(std::min(4, periods)),
                          "--element-steps", std::to_string(c_.study.simulate_element_steps)});
    // First: the longest step of the stage (3 minutes on rotor 67, a validation NFRC 10-30 s)
    // starts at once instead of running alone on one core after the others.
    frcs.insert(frcs.begin(), simulate);
  }
  // One batch: nothing here waits for anything else here.
  frcs.insert(frcs.end(), crossings.begin(), crossings.end());
  if (!run_steps(frcs) || !continue_validations_beyond_the_range()) return false;
  for (const Probe& p : probes_) compare(p);
  if (start.fold > 0 || start.point >= 0) compare_simulation();
  return true;
}

// A validation NFRC that left through the start of its range (its branch turned back past
// omega_start) is computed again over a range widened beyond the start by one range width (at
// most to 5 % of it): the branch then runs through its turning point there and on, and every
// limit point it meets is compared.
bool Study::continue_validations_beyond_the_range() {
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

void Study::compare(const Probe& p) {
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

// Limit points of the tracking curves that no NFRC from the linear solution passes announce
// isolated branches: `isolas` follows each until it closes.
bool Study::isolas() {
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

Study::ResonanceStart Study::resonance_start() const {
  if (c_.study.simulate_periods <= 0 || c_.outputs.empty()) return {};
  const long point = resonance_simulation_point(dir_ + "/nfrc", limit_points_, first_output());
  if (point < 0) return {};
  return {fold_ending_the_stable_stretch(dir_ + "/nfrc", point, limit_points_), point};
}

// The fold search's start that held the orbit (or, when none did, its last) compared with the
// HBM point it started from, the search itself beside it; or the one integration from a point.
void Study::compare_simulation() {
  const json s = read_summary(dir_ + "/simulate");
  if (!s.contains("fold_search")) {
    const long point = s["options"]["simulation"].value("point", 0L);
    summary_["simulation"] = compare_with_simulation(dir_ + "/nfrc", point, s, c_.outputs);
    save();
    return;
  }
  const json& search = s["fold_search"];
  const json runs = search.value("runs", json::array());
  if (runs.empty()) return;
  const json& compared = search.contains("held") ? search["held"] : runs.back();
  const std::string folder = compared.value("folder", "");
  json& simulation = summary_["simulation"] =
      compare_with_simulation(dir_ + "/nfrc", compared.value("point", 0L), read_summary(dir_ + "/simulate/" + folder), c_.outputs);
  simulation["folder"] = "simulate/" + folder;
  simulation["fold_search"] = search;
  save();
}

std::optional<Study::IsolaSimulation> Study::isola_simulation_step() const {
  if (c_.study.simulate_periods <= 0 || c_.outputs.empty()) return std::nullopt;
  json tracking = json::array();
  for (const StudyTrack& t : tracked_)
    if (const auto e = entries_.find(t.parameter); e != entries_.end()) tracking.push_back(e->second);
  const auto at = stable_isola_point(dir_, tracking, first_output());
  if (!at) return std::nullopt;
  const int periods = c_.study.simulate_periods;
  // `simulate --from` takes the isola's parameter values from its folder's summary.
  const std::string from = dir_ + "/" + at->folder;
  std::vector<std::string> args{"simulate",         o_.common.case_path,
                                "--from",           from,
                                "--point",          std::to_string(at->point),
                                "--max-periods",    std::to_string(periods),
                                "--record-periods", std::to_string(std::min(4, periods)),
                                "--element-steps",  std::to_string(c_.study.simulate_element_steps)};
  return IsolaSimulation{{"simulate_isola", args, false}, from, *at};
}

void Study::record_isola_simulation(const IsolaSimulation& run) {
  summary_["isola_simulation"] = compare_with_simulation(run.from, run.at.point, read_summary(dir_ + "/simulate_isola"), c_.outputs);
  summary_["isola_simulation"]["folder"] = run.at.folder;
  summary_["isola_simulation"]["stable_margin"] = run.at.margin;
  save();
}

bool Study::isola_simulation_and_convergence() {
  const std::optional<IsolaSimulation> isola = isola_simulation_step();
  const std::optional<Step> refined = refined_nfrc_step();
  std::vector<Step> batch;  // the integration first: the longer of the two
  if (isola) batch.push_back(isola->step);
  if (refined) batch.push_back(*refined);
  stage_ = isola ? kIsolaSimulation : kConvergence;
  if (!run_steps(batch)) return false;
  if (isola) record_isola_simulation(*isola);
  return !refined || convergence_tracking();
}

}  // namespace hbtrack::cli
