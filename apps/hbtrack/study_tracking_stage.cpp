// The study's tracking stages (study.hpp): every limit point of the nominal NFRC followed in each
// parameter, and the families only a validation NFRC meets, tracked from it.
#include <algorithm>
#include <cmath>

#include "cli_common.hpp"
#include "hbtrack/runs/special_point_start.hpp"
#include "result_folder.hpp"
#include "study.hpp"
#include "study_comparisons.hpp"
#include "study_curves.hpp"
#include "study_plan.hpp"

namespace hbtrack::cli {

using nlohmann::json;

namespace {

// The same extremum reached again (a curve that passes it twice, or the other LP's curve).
bool already_listed(const json& extrema, const TrackingCurve::Extremum& e) {
  for (const auto& x : extrema)
    if (x["type"] == e.type && std::abs(x["value"].get<double>() - e.value) <= 1e-9 * std::abs(e.value) &&
        std::abs(x["omega"].get<double>() - e.omega) <= 1e-9 * std::abs(e.omega))
      return true;
  return false;
}

}  // namespace

// Round k follows the k-th limit point in every parameter at once; a limit point that already
// lies on an earlier curve of the same parameter (the two folds of one cusp) is not tracked again.
bool Study::tracking() {
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

void Study::add_curve(const StudyTrack& t, size_t lp, double omega, const std::string& folder) {
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

bool Study::ns_pd_tracking() {
  if (!c_.study.track_ns_pd) return true;
  stage_ = kTracking;
  const json points = summary_["nfrc"]["special_points"];
  std::vector<Step> steps;
  std::vector<json> entries;  // the curves table's row of each step, and its parameter
  for (const SpecialPointType type : {SpecialPointType::neimark_sacker, SpecialPointType::period_doubling}) {
    const std::string name = to_string(type), flag = type == SpecialPointType::neimark_sacker ? "--ns" : "--pd";
    const std::vector<size_t> rows = runs::special_point_rows(points, type);  // K in omega order, as `track --ns K`
    for (size_t k = 0; k < rows.size(); ++k)
      for (const StudyTrack& t : tracked_) {
        const std::string K = std::to_string(k + 1);
        steps.push_back(
            {"track_" + t.parameter + "_" + flag.substr(2) + K,
             {"track", o_.common.case_path, "--from", dir_ + "/nfrc", flag, K, "--param", t.parameter, "--range",
              number_text(t.min) + ":" + number_text(t.max), "--set", "continuation.max_points=" + std::to_string(c_.study.max_points)},
             false});
        entries.push_back({{"parameter", t.parameter}, {"point", name + K}, {"omega", points[rows[k]].value("omega", 0.0)}});
      }
  }
  if (!run_steps(steps)) return false;
  for (size_t i = 0; i < steps.size(); ++i) {
    const json s = read_summary(dir_ + "/" + steps[i].folder);
    json curve = entries[i];
    const std::string parameter = curve["parameter"];
    curve.erase("parameter");
    curve.update({{"folder", steps[i].folder},
                  {"points", s.value("points", 0)},
                  {"stop_reason", s.value("stop_reason", "")},
                  {"closed", s.value("closed", false)},
                  {"wall_s", s["timings"].value("wall_s", 0.0)}});
    entries_[parameter]["curves"].push_back(curve);
  }
  return true;
}

// A validation NFRC's limit point on no tracking curve belongs to a family no limit point of the
// nominal NFRC leads to: it is tracked from that NFRC (`track_P_addedK/`, at most
// study.max_added_curves per parameter, one per parameter at a time so that a second limit
// point of the same family is not tracked twice), then the crossings at every validation value
// of P are located again with every curve (`crossings_P_J_all/`) and the NFRCs compared again.
bool Study::added_families() {
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

}  // namespace hbtrack::cli
